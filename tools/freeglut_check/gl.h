/* The reference programs on real freeglut (a double-buffered window on Xvfb), read back to PPM:
   glutDisplayFunc, glutReshapeFunc, glutInitDisplayMode and glutMainLoop are caught here. */
#include <GL/gl.h>
#include <GL/glu.h>
/* freeglut.h: the reference programs call freeglut's extensions too (glutStrokeHeight). */
#include <GL/freeglut.h>
void fg_display_func(void (*f)(void));
void fg_reshape_func(void (*f)(int, int));
void fg_init_display_mode(unsigned int mode);
void fg_main_loop(void);
#define glutDisplayFunc fg_display_func
#define glutReshapeFunc fg_reshape_func
#define glutInitDisplayMode fg_init_display_mode
#define glutMainLoop fg_main_loop
