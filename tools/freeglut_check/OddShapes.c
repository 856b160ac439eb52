// OddShapes.c: GLUT's shapes with odd arguments (3 slices and 2 stacks, a negative radius, size and
// height, a torus of 2 sides, a one-slice wire cone, zero slices or stacks that draw nothing), for
// tools/freeglut_check/check.sh: the stand-in must draw what freeglut draws here too.
#include "gl.h"
void Reshape(int w, int h) { glViewport(0,0,w,h); glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(-4,4,-2,2,-5,5); glMatrixMode(GL_MODELVIEW); glLoadIdentity(); }
void Display(void) {
  glClear(GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING); glEnable(GL_LIGHT0); glEnable(GL_DEPTH_TEST);
  glRotatef(20,1,1,0);
  glPushMatrix(); glTranslatef(-3,1,0); glutSolidSphere(0.8,3,2); glTranslatef(0,-2,0); glutSolidSphere(-0.7,5,3); glPopMatrix();
  glPushMatrix(); glTranslatef(-1,1,0); glutSolidCone(0.8,-1.0,3,1); glTranslatef(0,-2,0); glutSolidTorus(0.3,0.6,2,2); glPopMatrix();
  glPushMatrix(); glTranslatef(1,1,0); glutSolidCube(-1.0); glTranslatef(0,-2,0); glutSolidTorus(0.2,0.6,3,5); glPopMatrix();
  glDisable(GL_LIGHTING);
  glPushMatrix(); glTranslatef(3,1,0); glutWireSphere(0.8,3,2); glutWireCone(0.5,1,1,1); glTranslatef(0,-2,0); glutWireTorus(0.3,0.6,2,3); glutWireCube(0.4); glPopMatrix();
  glutSolidSphere(1,0,5); glutSolidSphere(1,5,1); glutSolidCone(1,1,0,3); glutSolidCone(1,1,3,0); glutWireTorus(1,1,1,5);
  glFlush();
}
int main(int argc, char **argv) { glutInit(&argc, argv); glutInitDisplayMode(GLUT_RGB|GLUT_DEPTH); glutInitWindowSize(400,200); glutCreateWindow("odd"); glutReshapeFunc(Reshape); glutDisplayFunc(Display); glutMainLoop(); return 0; }
