/* GL/glew.h for gleval: what the GLEW of 2010s textbooks is used for, answered by gleval itself.
 *
 * A program written for GLEW calls `glewExperimental = GL_TRUE; glewInit();` after making its
 * window and then calls GL. Here glewInit succeeds (GLEW_OK) once a gleval context is current
 * (after glutCreateWindow), and the GL entry points are gleval's own, declared by <GL/gl.h>:
 * every function gleval has is callable directly, none is a null pointer. GLEW_VERSION_1_1 is
 * true; later versions and extensions answer as gleval's glGetString does (GL 1.1, no
 * extensions). Build with capi/glevalcc, which drops -lGLEW as it drops -lGL. */
#ifndef __glew_h__
#define __glew_h__
#define __GLEW_H__
#include <GL/gl.h>
#include <GL/glu.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLEW_OK 0
#define GLEW_NO_ERROR 0
#define GLEW_ERROR_NO_GL_VERSION 1
#define GLEW_ERROR_GL_VERSION_10_ONLY 2
#define GLEW_ERROR_GLX_VERSION_11_ONLY 3
#define GLEW_ERROR_NO_GLX_DISPLAY 4
#define GLEW_VERSION 1
#define GLEW_VERSION_MAJOR 2
#define GLEW_VERSION_MINOR 3
#define GLEW_VERSION_MICRO 4

/* Set before glewInit by programs for core profiles; kept, and changes nothing here. */
extern GLboolean glewExperimental;

GLenum glewInit(void);
GLboolean glewIsSupported(const char *name);
GLboolean glewGetExtension(const char *name);
const GLubyte *glewGetErrorString(GLenum error);
const GLubyte *glewGetString(GLenum name);

#define glewIsExtensionSupported(x) glewIsSupported(x)
#define GLEW_VERSION_1_1 glewIsSupported("GL_VERSION_1_1")
#define GLEW_VERSION_1_2 glewIsSupported("GL_VERSION_1_2")
#define GLEW_VERSION_1_3 glewIsSupported("GL_VERSION_1_3")
#define GLEW_VERSION_1_4 glewIsSupported("GL_VERSION_1_4")
#define GLEW_VERSION_1_5 glewIsSupported("GL_VERSION_1_5")
#define GLEW_VERSION_2_0 glewIsSupported("GL_VERSION_2_0")
#define GLEW_VERSION_2_1 glewIsSupported("GL_VERSION_2_1")
#define GLEW_VERSION_3_0 glewIsSupported("GL_VERSION_3_0")

#ifdef __cplusplus
}
#endif
#endif /* __glew_h__ */
