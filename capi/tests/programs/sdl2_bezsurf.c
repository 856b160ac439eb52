/* SDL2: the bezsurf scene (bezsurf_scene.h) in a 400x400 SDL_WINDOW_OPENGL window titled
   "bezsurf sdl2", redrawn every 100 ms with SDL_GL_SwapWindow; exits after 3 s.
     cc -O1 -o sdl2_bezsurf sdl2_bezsurf.c $(sdl2-config --cflags --libs) -lGL -lm */
#include <SDL.h>
#include <stdio.h>
#include "bezsurf_scene.h"

int main(int argc, char **argv) {
  SDL_Window *win;
  SDL_GLContext ctx;
  Uint32 start;
  (void)argc; (void)argv;
  if (SDL_Init(SDL_INIT_VIDEO) != 0) { fprintf(stderr, "sdl2_bezsurf: %s\n", SDL_GetError()); return 1; }
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 16);
  win = SDL_CreateWindow("bezsurf sdl2", 0, 0, BEZSURF_SIZE, BEZSURF_SIZE, SDL_WINDOW_OPENGL | SDL_WINDOW_SHOWN);
  if (!win) { fprintf(stderr, "sdl2_bezsurf: SDL_CreateWindow: %s\n", SDL_GetError()); return 1; }
  ctx = SDL_GL_CreateContext(win);
  if (!ctx) { fprintf(stderr, "sdl2_bezsurf: SDL_GL_CreateContext: %s\n", SDL_GetError()); return 1; }
  printf("GL_VENDOR %s\nGL_RENDERER %s\n", (const char *)glGetString(GL_VENDOR), (const char *)glGetString(GL_RENDERER));
  fflush(stdout);
  bezsurf_init();
  start = SDL_GetTicks();
  while (SDL_GetTicks() - start < 3000) {
    SDL_Event ev;
    int w, h;
    while (SDL_PollEvent(&ev))
      if (ev.type == SDL_QUIT || ev.type == SDL_KEYDOWN) goto done;
    SDL_GL_GetDrawableSize(win, &w, &h);
    bezsurf_reshape(w, h);
    bezsurf_display();
    SDL_GL_SwapWindow(win);
    SDL_Delay(100);
  }
done:
  SDL_GL_DeleteContext(ctx);
  SDL_DestroyWindow(win);
  SDL_Quit();
  return 0;
}
