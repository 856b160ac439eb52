/* GLUT's menus are the program's, not a window's (freeglut 3.4): a menu made in window 1 is
   current in window 2, window 2's next menu gets the next id, an entry added there shows in
   window 1, and a destroyed menu cannot be set. menus.log is what real freeglut printed under
   Xvfb (gcc Menus.c -lglut -lGL; DISPLAY=:N ./a.out); capi/tests/glut.sh runs it on gleval. */
#include <GL/freeglut.h>
#include <stdio.h>
static int w1, w2, m1, m2;
static void pick(int v) { (void)v; }
static void display(void) { glClear(GL_COLOR_BUFFER_BIT); glFlush(); }
int main(int argc, char **argv) {
  glutInit(&argc, argv);
  glutInitWindowSize(64, 64);
  w1 = glutCreateWindow("one");
  glutDisplayFunc(display);
  m1 = glutCreateMenu(pick);
  glutAddMenuEntry("a", 1);
  glutAttachMenu(GLUT_RIGHT_BUTTON);
  w2 = glutCreateWindow("two");
  glutDisplayFunc(display);
  printf("in window 2: current menu %d (m1 %d), items %d\n", glutGetMenu(), m1, glutGet(GLUT_MENU_NUM_ITEMS));
  m2 = glutCreateMenu(pick);
  printf("second menu id %d\n", m2);
  glutSetMenu(m1);
  glutAddMenuEntry("b", 2);
  printf("menu %d now has %d items\n", glutGetMenu(), glutGet(GLUT_MENU_NUM_ITEMS));
  glutSetWindow(w1);
  printf("in window 1: current menu %d, items %d\n", glutGetMenu(), glutGet(GLUT_MENU_NUM_ITEMS));
  glutDestroyMenu(m2);
  glutSetMenu(m2);
  printf("after destroying %d: current %d\n", m2, glutGetMenu());
  return 0;
}
