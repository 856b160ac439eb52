/* Plain Xlib + GLX: the bezsurf scene (bezsurf_scene.h) in a 400x400 window titled
   "bezsurf glx", drawn on Expose and then every 100 ms, glXSwapBuffers; exits after 3 s.
     cc -O1 -o glx_bezsurf glx_bezsurf.c -lGL -lX11 -lm */
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/time.h>
#include <unistd.h>
#include "bezsurf_scene.h"

static double now(void) {
  struct timeval tv;
  gettimeofday(&tv, NULL);
  return tv.tv_sec + tv.tv_usec / 1e6;
}

int main(void) {
  int attributes[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16, None};
  Display *dpy = XOpenDisplay(NULL);
  XVisualInfo *vi;
  XSetWindowAttributes swa;
  Window win;
  GLXContext ctx;
  Atom wm_delete;
  int exposed = 0, width = BEZSURF_SIZE, height = BEZSURF_SIZE;
  double start, next = 0;
  if (!dpy) { fprintf(stderr, "glx_bezsurf: cannot open display\n"); return 1; }
  vi = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
  if (!vi) { fprintf(stderr, "glx_bezsurf: no RGBA double-buffered visual with depth\n"); return 1; }
  swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
  swa.border_pixel = 0;
  swa.background_pixel = 0;
  swa.event_mask = ExposureMask | StructureNotifyMask | KeyPressMask;
  win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, width, height, 0, vi->depth,
                      InputOutput, vi->visual, CWColormap | CWBorderPixel | CWBackPixel | CWEventMask, &swa);
  XStoreName(dpy, win, "bezsurf glx");
  wm_delete = XInternAtom(dpy, "WM_DELETE_WINDOW", False);
  XSetWMProtocols(dpy, win, &wm_delete, 1);
  ctx = glXCreateContext(dpy, vi, NULL, True);
  if (!ctx) { fprintf(stderr, "glx_bezsurf: glXCreateContext failed\n"); return 1; }
  XMapWindow(dpy, win);
  if (!glXMakeCurrent(dpy, win, ctx)) { fprintf(stderr, "glx_bezsurf: glXMakeCurrent failed\n"); return 1; }
  printf("GL_VENDOR %s\nGL_RENDERER %s\n", (const char *)glGetString(GL_VENDOR), (const char *)glGetString(GL_RENDERER));
  fflush(stdout);
  bezsurf_init();
  start = now();
  while (now() - start < 3.0) {
    int redraw = 0;
    while (XPending(dpy)) {
      XEvent ev;
      XNextEvent(dpy, &ev);
      if (ev.type == Expose && ev.xexpose.count == 0) { exposed = 1; redraw = 1; }
      else if (ev.type == ConfigureNotify) { width = ev.xconfigure.width; height = ev.xconfigure.height; }
      else if (ev.type == KeyPress || (ev.type == ClientMessage && (Atom)ev.xclient.data.l[0] == wm_delete)) goto done;
    }
    if (exposed && (redraw || now() >= next)) {
      bezsurf_reshape(width, height);
      bezsurf_display();
      glXSwapBuffers(dpy, win);
      next = now() + 0.1;
    }
    usleep(10000);
  }
done:
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, ctx);
  XDestroyWindow(dpy, win);
  XCloseDisplay(dpy);
  return 0;
}
