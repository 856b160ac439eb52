/* The scene the capi/tests/programs/ C and C++ programs draw (the Python ones repeat it): the
   Red Book's bicubic Bezier surface (glMap2f, glMapGrid2f, glEvalMesh2), lit by GL_LIGHT0 with
   automatic normals, rotated 85 degrees about (1, 1, 1) in an orthographic view, and in front
   of it an unlit yellow glMap1f curve, on a dark blue background; 400x400. */
#ifndef BEZSURF_SCENE_H
#define BEZSURF_SCENE_H
#include <GL/gl.h>

#define BEZSURF_SIZE 400

static const GLfloat bezsurf_ctrl[4][4][3] = {
  {{-1.5f, -1.5f, 4.0f}, {-0.5f, -1.5f, 2.0f}, {0.5f, -1.5f, -1.0f}, {1.5f, -1.5f, 2.0f}},
  {{-1.5f, -0.5f, 1.0f}, {-0.5f, -0.5f, 3.0f}, {0.5f, -0.5f, 0.0f}, {1.5f, -0.5f, -1.0f}},
  {{-1.5f, 0.5f, 4.0f}, {-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 3.0f}, {1.5f, 0.5f, 4.0f}},
  {{-1.5f, 1.5f, -2.0f}, {-0.5f, 1.5f, -2.0f}, {0.5f, 1.5f, 0.0f}, {1.5f, 1.5f, -1.0f}}};

static const GLfloat bezsurf_curve[4][3] = {
  {-3.5f, -3.0f, 6.0f}, {-1.5f, 3.5f, 6.0f}, {1.5f, -3.5f, 6.0f}, {3.5f, 3.0f, 6.0f}};

static void bezsurf_init(void) {
  static const GLfloat ambient[] = {0.2f, 0.2f, 0.2f, 1.0f};
  static const GLfloat position[] = {0.0f, 0.0f, 2.0f, 1.0f};
  static const GLfloat diffuse[] = {0.6f, 0.6f, 0.6f, 1.0f};
  static const GLfloat specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
  static const GLfloat shininess[] = {50.0f};
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &bezsurf_ctrl[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(20, 0.0f, 1.0f, 20, 0.0f, 1.0f);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &bezsurf_curve[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

static void bezsurf_reshape(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-4.0, 4.0, -4.0 * h / w, 4.0 * h / w, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void bezsurf_display(void) {
  int i;
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPushMatrix();
  glRotatef(85.0f, 1.0f, 1.0f, 1.0f);
  glEvalMesh2(GL_FILL, 0, 20, 0, 20);
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glColor3f(1.0f, 1.0f, 0.0f);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i <= 30; i++) glEvalCoord1f((GLfloat)i / 30.0f);
  glEnd();
  glEnable(GL_LIGHTING);
}
#endif
