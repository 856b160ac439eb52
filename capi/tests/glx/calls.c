/* GLX and EGL calls, good and bad, each answer printed: run on real Mesa and on gleval
 * (capi/tests/glx.sh), the two outputs must be the same. What legitimately differs between
 * implementations (strings, how many configurations) is not printed; what GL and the window
 * systems specify is: return values, error codes, drawn pixels. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int glx_error_base, x_errors, last_error;

static int on_error(Display *dpy, XErrorEvent *e) {
  (void)dpy;
  x_errors++;
  last_error = e->error_code;
  return 0;
}

/* The last X error since the previous report, as GLX's name or X's number. */
static const char *x_error(Display *dpy) {
  static char text[32];
  XSync(dpy, False);
  if (!x_errors) return "none";
  x_errors = 0;
  int glx = last_error - glx_error_base;
  static const char *names[] = {"GLXBadContext", "GLXBadContextState", "GLXBadDrawable", "GLXBadPixmap",
                                "GLXBadContextTag", "GLXBadCurrentWindow", "GLXBadRenderRequest",
                                "GLXBadLargeRequest", "GLXUnsupportedPrivateRequest", "GLXBadFBConfig",
                                "GLXBadPbuffer", "GLXBadCurrentDrawable", "GLXBadWindow", "GLXBadProfileARB"};
  if (glx >= 0 && glx < 14) return names[glx];
  snprintf(text, sizeof text, "X error %d", last_error);
  return text;
}

/* A call's answer, then the error it raised (C leaves the order of a call's arguments open). */
#define SAY_X(dpy, what, call, yes, no)                                                      \
  do {                                                                                       \
    int said_ = (call) != 0;                                                                 \
    printf("%s: %s, %s\n", what, said_ ? yes : no, x_error(dpy));                             \
  } while (0)
#define SAY_EGL(what, call, yes, no)                                                         \
  do {                                                                                       \
    int said_ = (call) != 0;                                                                 \
    printf("%s: %s, %s\n", what, said_ ? yes : no, egl_error());                               \
  } while (0)

/* Set for gleval's run: the lines where Mesa departs from the specifications are printed. */
static int gleval_only;

static void probe(const char *what) {
  unsigned char p[4] = {0};
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  printf("%s: pixel %d %d %d %d, GL error 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

static void draw_green(void) {
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0, 1, 0);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
}

static GLXContext shared_ctx;
static Display *shared_dpy;
static Window shared_win;

static void *other_thread(void *unused) {
  (void)unused;
  Bool ok = glXMakeCurrent(shared_dpy, shared_win, shared_ctx);
  /* GLX 1.4 §3.3.7 says BadAccess; Mesa answers True with no error. */
  const char *error = x_error(shared_dpy);
  if (gleval_only)
    printf("glXMakeCurrent of a context current in another thread: %s, %s\n", ok ? "True" : "False", error);
  return NULL;
}

static void glx(Display *dpy) {
  int event_base;
  printf("glXQueryExtension: %s\n", glXQueryExtension(dpy, &glx_error_base, &event_base) ? "True" : "False");
  int major = 0, minor = 0;
  glXQueryVersion(dpy, &major, &minor);
  printf("GLX at least 1.3: %s\n", major > 1 || minor >= 3 ? "yes" : "no");

  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_DEPTH_SIZE, 16, None};
  XVisualInfo *vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
  printf("glXChooseVisual (RGBA, double, depth): %s\n", vi ? "a visual" : "NULL");
  int ci[] = {GLX_DOUBLEBUFFER, None};
  XVisualInfo *none = glXChooseVisual(dpy, DefaultScreen(dpy), ci);
  printf("glXChooseVisual (colour index): %s\n", none ? "a visual" : "NULL");
  int value = -1;
  glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &value);
  printf("glXGetConfig GLX_DOUBLEBUFFER: %d\n", value);
  glXGetConfig(dpy, vi, GLX_RGBA, &value);
  printf("glXGetConfig GLX_RGBA: %d\n", value);
  printf("glXGetConfig of an attribute GLX has not: %d\n", glXGetConfig(dpy, vi, 0x7777, &value));

  XSetWindowAttributes swa = {0};
  swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
  Window win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, 64, 48, 0, vi->depth, InputOutput, vi->visual,
                             CWColormap, &swa);
  GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
  printf("glXCreateContext: %s\n", ctx ? "a context" : "NULL");
  printf("glXGetCurrentContext before: %s\n", glXGetCurrentContext() ? "a context" : "NULL");
  XSelectInput(dpy, win, StructureNotifyMask);
  XMapWindow(dpy, win);
  XEvent ev;
  do XNextEvent(dpy, &ev); while (ev.type != MapNotify);
  SAY_X(dpy, "glXMakeCurrent", glXMakeCurrent(dpy, win, ctx), "True", "False");
  printf("glXGetCurrentContext: %s\n", glXGetCurrentContext() == ctx ? "ctx" : "other");
  printf("glXGetCurrentDrawable: %s\n", glXGetCurrentDrawable() == win ? "win" : "other");
  printf("glXGetCurrentDisplay: %s\n", glXGetCurrentDisplay() == dpy ? "dpy" : "other");
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  printf("initial viewport: %d %d %d %d\n", viewport[0], viewport[1], viewport[2], viewport[3]);
  GLint db = -1;
  glGetIntegerv(GL_DRAW_BUFFER, &db);
  printf("GL_DRAW_BUFFER: 0x%x\n", db);
  draw_green();
  probe("back buffer after drawing");
  glXSwapBuffers(dpy, win);
  /* Mesa's llvmpipe reads black from a front buffer here (piglit's read-front tests fail on
   * it): printed on gleval only. */
  if (gleval_only) {
    glReadBuffer(GL_FRONT);
    probe("front buffer after the swap");
    glReadBuffer(GL_BACK);
  }

  /* X's "fixed" font as bitmap lists (glXUseXFont), drawn: which pixels are lit. */
  Font font = XLoadFont(dpy, "fixed");
  GLuint base = glGenLists(96);
  glXUseXFont(font, 32, 96, (int)base);
  /* Mesa 22.3 sets GL_OUT_OF_MEMORY here, even for one glyph, and makes the lists all the
   * same (drawn below, pixel for pixel): printed on gleval only, which sets no error. */
  GLenum font_error = glGetError();
  if (gleval_only) printf("glXUseXFont: GL error 0x%x\n", font_error);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glRasterPos2f(-0.95f, -0.3f);
  glListBase(base - 32);
  glCallLists(6, GL_UNSIGNED_BYTE, "gleval");
  static unsigned char text[64 * 48 * 4];
  glReadPixels(0, 0, 64, 48, GL_RGBA, GL_UNSIGNED_BYTE, text);
  unsigned long lit = 0, where = 0;
  for (int i = 0; i < 64 * 48; i++)
    if (text[4 * i]) lit++, where = where * 31 + (unsigned long)i;
  printf("glXUseXFont \"gleval\": %lu pixels lit, at %lx\n", lit, where);
  if (getenv("SHOW_TEXT")) for (int y = 47; y >= 0; y--) { for (int x = 0; x < 64; x++) putchar(text[4 * (y * 64 + x)] ? 35 : 46); putchar(10); }
  glListBase(0);

  printf("glXGetProcAddress(glBegin): %s\n", glXGetProcAddressARB((const GLubyte *)"glBegin") ? "found" : "NULL");
  /* Mesa hands out a stub for any name; gleval NULL for what it lacks. */
  if (gleval_only) printf("glXGetProcAddress(glNoSuchFunction): %s\n",
         glXGetProcAddressARB((const GLubyte *)"glNoSuchFunctionEXT") ? "found" : "NULL");

  /* Bad input. */
  SAY_X(dpy, "glXMakeCurrent with a bad context", glXMakeCurrent(dpy, win, (GLXContext)&value), "True", "False");
  SAY_X(dpy, "glXMakeCurrent with a context and no drawable", glXMakeCurrent(dpy, None, ctx), "True", "False");
  SAY_X(dpy, "glXMakeCurrent back", glXMakeCurrent(dpy, win, ctx), "True", "False");
  printf("glXIsDirect: %s\n", glXIsDirect(dpy, ctx) ? "True" : "False");

  int nconfigs = 0;
  int fb_attribs[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_DOUBLEBUFFER, False, None};
  GLXFBConfig *configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), fb_attribs, &nconfigs);
  printf("glXChooseFBConfig (pbuffer, single): %s\n", nconfigs > 0 ? "some" : "none");
  int samples[] = {GLX_SAMPLES, 64, None};
  int nsamples = -1;
  GLXFBConfig *none_configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), samples, &nsamples);
  printf("glXChooseFBConfig (64 samples): %d, %s\n", nsamples, none_configs ? "a list" : "NULL");
  typedef GLXContext (*CreateContextAttribs)(Display *, GLXFBConfig, GLXContext, Bool, const int *);
  CreateContextAttribs create =
      (CreateContextAttribs)glXGetProcAddressARB((const GLubyte *)"glXCreateContextAttribsARB");
  int bad_version[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 7, None};
  GLXContext bad = create(dpy, configs[0], NULL, True, bad_version);
  SAY_X(dpy, "glXCreateContextAttribsARB 1.7", bad, "a context", "NULL");
  int above[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 9, GLX_CONTEXT_MINOR_VERSION_ARB, 0, None};
  bad = create(dpy, configs[0], NULL, True, above);
  SAY_X(dpy, "glXCreateContextAttribsARB 9.0", bad, "a context", "NULL");
  int bad_attrib[] = {0x7777, 1, None};
  bad = create(dpy, configs[0], NULL, True, bad_attrib);
  SAY_X(dpy, "glXCreateContextAttribsARB unknown attribute", bad, "a context", "NULL");
  GLXContext plain = create(dpy, configs[0], NULL, True, NULL);
  SAY_X(dpy, "glXCreateContextAttribsARB NULL list", plain, "a context", "NULL");

  int pb_attribs[] = {GLX_PBUFFER_WIDTH, 32, GLX_PBUFFER_HEIGHT, 16, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, configs[0], pb_attribs);
  SAY_X(dpy, "glXCreatePbuffer", pb, "a pbuffer", "None");
  unsigned int w = 0, h = 0;
  glXQueryDrawable(dpy, pb, GLX_WIDTH, &w);
  glXQueryDrawable(dpy, pb, GLX_HEIGHT, &h);
  printf("pbuffer size: %u x %u\n", w, h);
  SAY_X(dpy, "glXMakeContextCurrent on the pbuffer", glXMakeContextCurrent(dpy, pb, pb, plain), "True", "False");
  glGetIntegerv(GL_VIEWPORT, viewport);
  printf("pbuffer viewport: %d %d %d %d\n", viewport[0], viewport[1], viewport[2], viewport[3]);
  draw_green();
  glFinish();
  probe("pbuffer");
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyPbuffer(dpy, pb);
  XFree(configs);

  /* A context current in this thread, bound from another. */
  glXMakeCurrent(dpy, win, ctx);
  shared_ctx = ctx, shared_dpy = dpy, shared_win = win;
  pthread_t t;
  pthread_create(&t, NULL, other_thread, NULL);
  pthread_join(t, NULL);
  /* Destroyed while current: still current until released. */
  glXDestroyContext(dpy, ctx);
  printf("destroyed while current, glXGetCurrentContext: %s\n", glXGetCurrentContext() == ctx ? "ctx" : "other");
  draw_green();
  probe("still drawing");
  SAY_X(dpy, "release", glXMakeCurrent(dpy, None, NULL), "True", "False");
  printf("glXGetCurrentContext after release: %s\n", glXGetCurrentContext() ? "a context" : "NULL");
  glXDestroyContext(dpy, plain);
  XDestroyWindow(dpy, win);
  XFree(vi);
}

static const char *egl_error(void) {
  switch (eglGetError()) {
  case EGL_SUCCESS: return "EGL_SUCCESS";
  case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
  case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
  case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
  case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
  case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
  case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
  case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
  case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
  case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
  default: return "another error";
  }
}

static EGLDisplay egl_dpy;
static EGLContext egl_ctx;

static void *egl_other_thread(void *unused) {
  (void)unused;
  eglBindAPI(EGL_OPENGL_API);
  EGLBoolean ok = eglMakeCurrent(egl_dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_ctx);
  SAY_EGL("eglMakeCurrent of a context current in another thread", ok, "EGL_TRUE", "EGL_FALSE");
  return NULL;
}

static void egl(void) {
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
      (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
  const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  printf("client extensions name the surfaceless platform: %s\n",
         client && strstr(client, "EGL_MESA_platform_surfaceless") ? "yes" : "no");
  EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  printf("eglGetPlatformDisplayEXT (surfaceless): %s\n", dpy ? "a display" : "EGL_NO_DISPLAY");
  EGLint major, minor;
  SAY_EGL("eglInitialize of a bad display", eglInitialize((EGLDisplay)&major, &major, &minor), "EGL_TRUE", "EGL_FALSE");
  SAY_EGL("eglChooseConfig before eglInitialize", eglChooseConfig(dpy, NULL, NULL, 0, &major), "EGL_TRUE", "EGL_FALSE");
  SAY_EGL("eglInitialize", eglInitialize(dpy, &major, &minor), "EGL_TRUE", "EGL_FALSE");
  printf("EGL at least 1.4: %s\n", major > 1 || minor >= 4 ? "yes" : "no");
  EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8,
                      EGL_DEPTH_SIZE, 16, EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  eglChooseConfig(dpy, attribs, &config, 1, &n);
  SAY_EGL("eglChooseConfig (OpenGL, pbuffer)", n > 0, "some", "none");
  EGLint bad_attrib[] = {0x7777, 1, EGL_NONE};
  SAY_EGL("eglChooseConfig of an attribute EGL has not", eglChooseConfig(dpy, bad_attrib, &config, 1, &n), "EGL_TRUE", "EGL_FALSE");
  eglChooseConfig(dpy, attribs, &config, 1, &n);
  SAY_EGL("eglBindAPI(EGL_OPENGL_API)", eglBindAPI(EGL_OPENGL_API), "EGL_TRUE", "EGL_FALSE");
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  SAY_EGL("eglCreateContext", ctx, "a context", "EGL_NO_CONTEXT");
  EGLint bad_ctx[] = {0x7777, 1, EGL_NONE};
  SAY_EGL("eglCreateContext with an attribute EGL has not", eglCreateContext(dpy, config, EGL_NO_CONTEXT, bad_ctx), "a context", "EGL_NO_CONTEXT");
  SAY_EGL("eglCreateContext with a bad config", eglCreateContext(dpy, (EGLConfig)&n, EGL_NO_CONTEXT, NULL), "a context", "EGL_NO_CONTEXT");
  EGLint pb_attribs[] = {EGL_WIDTH, 32, EGL_HEIGHT, 16, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, config, pb_attribs);
  SAY_EGL("eglCreatePbufferSurface", pb, "a surface", "EGL_NO_SURFACE");
  EGLint w = 0, h = 0;
  eglQuerySurface(dpy, pb, EGL_WIDTH, &w);
  eglQuerySurface(dpy, pb, EGL_HEIGHT, &h);
  printf("pbuffer size: %d x %d\n", w, h);
  SAY_EGL("eglMakeCurrent with a bad surface", eglMakeCurrent(dpy, (EGLSurface)&w, (EGLSurface)&w, ctx), "EGL_TRUE", "EGL_FALSE");
  SAY_EGL("eglMakeCurrent", eglMakeCurrent(dpy, pb, pb, ctx), "EGL_TRUE", "EGL_FALSE");
  printf("eglGetCurrentContext: %s\n", eglGetCurrentContext() == ctx ? "ctx" : "other");
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  printf("pbuffer viewport: %d %d %d %d\n", viewport[0], viewport[1], viewport[2], viewport[3]);
  draw_green();
  probe("EGL pbuffer");
  SAY_EGL("eglSwapBuffers on the pbuffer", eglSwapBuffers(dpy, pb), "EGL_TRUE", "EGL_FALSE");
  egl_dpy = dpy, egl_ctx = ctx;
  pthread_t t;
  pthread_create(&t, NULL, egl_other_thread, NULL);
  pthread_join(t, NULL);
  SAY_EGL("release", eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT), "EGL_TRUE", "EGL_FALSE");
  SAY_EGL("eglDestroySurface", eglDestroySurface(dpy, pb), "EGL_TRUE", "EGL_FALSE");
  SAY_EGL("eglDestroySurface again", eglDestroySurface(dpy, pb), "EGL_TRUE", "EGL_FALSE");
  SAY_EGL("eglDestroyContext", eglDestroyContext(dpy, ctx), "EGL_TRUE", "EGL_FALSE");
  SAY_EGL("eglTerminate", eglTerminate(dpy), "EGL_TRUE", "EGL_FALSE");
}

int main(int argc, char **argv) {
  gleval_only = argc > 2 && strcmp(argv[2], "gleval") == 0;
  if (argc > 1 && strcmp(argv[1], "egl") == 0) {
    egl();
    return 0;
  }
  Display *dpy = XOpenDisplay(NULL);
  if (!dpy) {
    fprintf(stderr, "no X display\n");
    return 1;
  }
  XSetErrorHandler(on_error);
  glx(dpy);
  XCloseDisplay(dpy);
  return 0;
}
