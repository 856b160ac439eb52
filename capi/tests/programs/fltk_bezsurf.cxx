// FLTK: the bezsurf scene (bezsurf_scene.h) in a top-level 400x400 Fl_Gl_Window titled
// "bezsurf fltk" (FL_RGB | FL_DOUBLE | FL_DEPTH), redrawn every 100 ms; exits after 3 s.
//   g++ -O1 -o fltk_bezsurf fltk_bezsurf.cxx $(fltk-config --use-gl --cxxflags --ldflags) -lGL -lm
#include <FL/Fl.H>
#include <FL/Fl_Gl_Window.H>
#include <FL/gl.h>
#include <cstdio>
#include <cstdlib>
#include "bezsurf_scene.h"

class BezsurfWindow : public Fl_Gl_Window {
 public:
  BezsurfWindow(int w, int h, const char *title) : Fl_Gl_Window(w, h, title) {
    mode(FL_RGB | FL_DOUBLE | FL_DEPTH);
  }
  void draw() override {
    if (!valid()) {
      static bool first = true;
      if (first) {
        std::printf("GL_VENDOR %s\nGL_RENDERER %s\n", (const char *)glGetString(GL_VENDOR),
                    (const char *)glGetString(GL_RENDERER));
        std::fflush(stdout);
        first = false;
      }
      bezsurf_init();
      bezsurf_reshape(pixel_w(), pixel_h());
    }
    bezsurf_display();
  }
};

static void tick(void *data) {
  static_cast<BezsurfWindow *>(data)->redraw();
  Fl::repeat_timeout(0.1, tick, data);
}

static void quit(void *) { std::exit(0); }

int main(int argc, char **argv) {
  BezsurfWindow win(BEZSURF_SIZE, BEZSURF_SIZE, "bezsurf fltk");
  win.position(0, 0);
  win.show(argc, argv);
  Fl::add_timeout(0.1, tick, &win);
  Fl::add_timeout(3.0, quit);
  return Fl::run();
}
