/* Random GLX and EGL calls on gleval (capi/tests/glx.sh): handles that are not handles (NULL,
 * addresses of other memory, destroyed ones), drawables that do not exist, attribute lists of
 * anything, contexts bound in two threads, destroyed while current, GL calls between. gleval
 * must answer each with GLX's, X's or EGL's error and never crash, hang or unwind; every X
 * error reaches the handler installed here (which counts them), every EGL error eglGetError.
 * Run on gleval only: handed such handles, Mesa's GLX (as any driver's) crashes.
 *
 *   fuzz CALLS SEED */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static uint64_t state = 88172645463325252ull;
static uint64_t next(void) { state ^= state << 13; state ^= state >> 7; state ^= state << 17; return state; }
static int pick(int n) { return (int)(next() % (uint64_t)n); }
#define ANY(a) ((a)[pick((int)(sizeof(a) / sizeof((a)[0])))])

static unsigned long x_errors;
static int on_error(Display *d, XErrorEvent *e) { (void)d; (void)e; x_errors++; return 0; }

static Display *dpy;
static Window win;
static long junk[64];
static GLXContext contexts[8];
static GLXDrawable drawables[8];
static GLXFBConfig configs[4];
static XVisualInfo *visual;

static const int attrib_names[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, GLX_CONTEXT_MINOR_VERSION_ARB, GLX_CONTEXT_FLAGS_ARB,
                                   GLX_CONTEXT_PROFILE_MASK_ARB, GLX_RENDER_TYPE, GLX_PBUFFER_WIDTH, GLX_PBUFFER_HEIGHT,
                                   GLX_LARGEST_PBUFFER, GLX_DOUBLEBUFFER, GLX_STENCIL_SIZE, GLX_SAMPLES, 0x7777, -1};
static const int values[] = {-1, 0, 1, 2, 3, 4, 7, 8, 24, 33, 300, 1 << 20, 0x7fffffff, GLX_RGBA_TYPE};

/* A list of up to 6 random pairs, ended by None. */
static int *attribs(int *list) {
  int n = pick(7), i = 0;
  for (; i < 2 * n; i += 2) {
    list[i] = ANY(attrib_names);
    list[i + 1] = ANY(values);
    if (list[i] == GLX_PBUFFER_WIDTH || list[i] == GLX_PBUFFER_HEIGHT) list[i + 1] &= 511;
    if (list[i] == 0) break;
  }
  list[i] = None;
  return list;
}

static GLXContext any_context(void) {
  switch (pick(4)) {
  case 0: return NULL;
  case 1: return (GLXContext)&junk[pick(64)];
  default: return contexts[pick(8)];
  }
}

static GLXDrawable any_drawable(void) {
  switch (pick(5)) {
  case 0: return None;
  case 1: return (GLXDrawable)(next() & 0x3fffffff);
  case 2: return win;
  default: return drawables[pick(8)];
  }
}

static GLXFBConfig any_config(void) {
  switch (pick(4)) {
  case 0: return NULL;
  case 1: return (GLXFBConfig)&junk[pick(64)];
  default: return configs[pick(4)];
  }
}

typedef GLXContext (*CreateAttribs)(Display *, GLXFBConfig, GLXContext, Bool, const int *);
static CreateAttribs create_attribs;

static void glx_call(void) {
  int list[16];
  unsigned int value;
  int k = pick(12);
  switch (k) {
  case 0: contexts[pick(8)] = glXCreateContext(dpy, pick(4) ? visual : NULL, any_context(), True); break;
  case 1: contexts[pick(8)] = glXCreateNewContext(dpy, any_config(), ANY(values), any_context(), True); break;
  case 2: contexts[pick(8)] = create_attribs(dpy, any_config(), any_context(), True, pick(5) ? attribs(list) : NULL); break;
  case 3: glXMakeCurrent(dpy, any_drawable(), any_context()); break;
  case 4: glXMakeContextCurrent(dpy, any_drawable(), any_drawable(), any_context()); break;
  case 5: {
    int i = pick(8);
    glXDestroyContext(dpy, contexts[i]);
    if (pick(2)) contexts[i] = NULL; /* else: kept, a destroyed handle */
    break;
  }
  case 6: drawables[pick(8)] = glXCreatePbuffer(dpy, any_config(), pick(5) ? attribs(list) : NULL); break;
  case 7: glXDestroyPbuffer(dpy, any_drawable()); break;
  case 8: glXSwapBuffers(dpy, any_drawable()); break;
  case 9: glXQueryDrawable(dpy, any_drawable(), ANY(attrib_names), &value); break;
  case 10: glXCopyContext(dpy, any_context(), any_context(), next()); break;
  default:
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
    unsigned char p[4 * 16];
    glReadPixels(pick(600) - 100, pick(600) - 100, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, p);
    glFinish();
    break;
  }
}

static EGLDisplay egl_dpy;
static EGLContext egl_contexts[4];
static EGLSurface egl_surfaces[4];
static EGLConfig egl_config;

static void egl_call(void) {
  static const EGLint names[] = {EGL_WIDTH, EGL_HEIGHT, EGL_LARGEST_PBUFFER, EGL_CONTEXT_MAJOR_VERSION,
                                 EGL_CONTEXT_MINOR_VERSION, EGL_RENDERABLE_TYPE, 0x7777};
  EGLint list[9] = {ANY(names), pick(600) - 50, ANY(names), pick(600) - 50, EGL_NONE};
  if (pick(3) == 0) list[2] = EGL_NONE;
  EGLContext c = pick(4) ? egl_contexts[pick(4)] : (EGLContext)&junk[pick(64)];
  EGLSurface s = pick(4) ? egl_surfaces[pick(4)] : (EGLSurface)&junk[pick(64)];
  EGLint v;
  switch (pick(8)) {
  case 0: egl_contexts[pick(4)] = eglCreateContext(egl_dpy, pick(4) ? egl_config : (EGLConfig)junk, pick(2) ? c : EGL_NO_CONTEXT, list); break;
  case 1: egl_surfaces[pick(4)] = eglCreatePbufferSurface(egl_dpy, pick(4) ? egl_config : NULL, list); break;
  case 2: eglMakeCurrent(egl_dpy, s, pick(2) ? s : EGL_NO_SURFACE, c); break;
  case 3: eglDestroyContext(pick(5) ? egl_dpy : (EGLDisplay)junk, c); break;
  case 4: eglDestroySurface(egl_dpy, s); break;
  case 5: eglSwapBuffers(egl_dpy, s); break;
  case 6: eglQuerySurface(egl_dpy, s, ANY(names), &v); break;
  default: glClear(GL_COLOR_BUFFER_BIT); glRectf(0, 0, 1, 1); break;
  }
  EGLint e = eglGetError();
  if (e < EGL_SUCCESS || e > EGL_CONTEXT_LOST) {
    printf("eglGetError answered 0x%x\n", e);
    exit(1);
  }
}

static unsigned long calls;

static void *second_thread(void *unused) {
  (void)unused;
  for (unsigned long i = 0; i < calls / 4; i++) {
    if (pick(2)) glXMakeCurrent(dpy, any_drawable(), any_context());
    else {
      glClear(GL_COLOR_BUFFER_BIT);
      glFlush();
    }
  }
  glXMakeCurrent(dpy, None, NULL);
  return NULL;
}

int main(int argc, char **argv) {
  calls = argc > 1 ? strtoul(argv[1], NULL, 10) : 2000;
  if (argc > 2) state += strtoull(argv[2], NULL, 10) * 0x9e3779b97f4a7c15ull;
  XInitThreads();
  dpy = XOpenDisplay(NULL);
  if (!dpy) return 2;
  XSetErrorHandler(on_error);
  int rgba[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16, None};
  visual = glXChooseVisual(dpy, DefaultScreen(dpy), rgba);
  XSetWindowAttributes swa = {0};
  swa.colormap = XCreateColormap(dpy, RootWindow(dpy, 0), visual->visual, AllocNone);
  win = XCreateWindow(dpy, RootWindow(dpy, 0), 0, 0, 100, 80, 0, visual->depth, InputOutput, visual->visual, CWColormap, &swa);
  XMapWindow(dpy, win);
  int n = 0;
  GLXFBConfig *all = glXGetFBConfigs(dpy, DefaultScreen(dpy), &n);
  for (int i = 0; i < 4 && i < n; i++) configs[i] = all[i * (n / 4)];
  create_attribs = (CreateAttribs)glXGetProcAddressARB((const GLubyte *)"glXCreateContextAttribsARB");
  pthread_t t;
  pthread_create(&t, NULL, second_thread, NULL);
  for (unsigned long i = 0; i < calls; i++) glx_call();
  pthread_join(t, NULL);
  glXMakeCurrent(dpy, None, NULL);

  egl_dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  eglInitialize(egl_dpy, NULL, NULL);
  eglBindAPI(EGL_OPENGL_API);
  EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  eglChooseConfig(egl_dpy, want, &egl_config, 1, &n);
  for (unsigned long i = 0; i < calls; i++) egl_call();
  eglMakeCurrent(egl_dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  printf("%lu GLX and %lu EGL calls, %lu X errors reported\n", calls, calls, x_errors);
  return 0;
}
