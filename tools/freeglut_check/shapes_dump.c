/* shapes_dump.c: calls each of freeglut 3.4's shapes once (some twice, at another size), with
 * glFinish after each so that arrays_dump.c prints what it drew; the first word of each line
 * names the call. Built and run by tools/freeglut_check/shapes.sh. */
#include <GL/freeglut.h>
#include <stdio.h>
#include <stdlib.h>

#define SHOW(name, call) do { printf("%s ", name); fflush(stdout); call; glFinish(); } while (0)

static void display(void)
{
    double o0[3] = {0, 0, 0}, o1[3] = {0.25, -0.5, 1.0};
    SHOW("solid_tetrahedron", glutSolidTetrahedron());
    SHOW("wire_tetrahedron", glutWireTetrahedron());
    SHOW("solid_octahedron", glutSolidOctahedron());
    SHOW("wire_octahedron", glutWireOctahedron());
    SHOW("solid_dodecahedron", glutSolidDodecahedron());
    SHOW("wire_dodecahedron", glutWireDodecahedron());
    SHOW("solid_icosahedron", glutSolidIcosahedron());
    SHOW("wire_icosahedron", glutWireIcosahedron());
    SHOW("solid_rhombic_dodecahedron", glutSolidRhombicDodecahedron());
    SHOW("wire_rhombic_dodecahedron", glutWireRhombicDodecahedron());
    SHOW("solid_cube_1.5", glutSolidCube(1.5));
    SHOW("wire_cube_0.75", glutWireCube(0.75));
    SHOW("solid_sponge_0", glutSolidSierpinskiSponge(0, o0, 1.0));
    SHOW("solid_sponge_2", glutSolidSierpinskiSponge(2, o1, 1.5));
    SHOW("wire_sponge_3", glutWireSierpinskiSponge(3, o1, 0.7));
    SHOW("solid_cylinder_1_2_7_3", glutSolidCylinder(1.0, 2.0, 7, 3));
    SHOW("wire_cylinder_0.5_1_5_2", glutWireCylinder(0.5, 1.0, 5, 2));
    SHOW("solid_cylinder_1_1_3_1", glutSolidCylinder(1.0, 1.0, 3, 1));
    SHOW("solid_teapot_1", glutSolidTeapot(1.0));
    SHOW("solid_teapot_0.5", glutSolidTeapot(0.5));
    SHOW("wire_teapot_1", glutWireTeapot(1.0));
    SHOW("wire_teapot_2", glutWireTeapot(2.0));
    SHOW("solid_teacup_1", glutSolidTeacup(1.0));
    SHOW("solid_teacup_2.5", glutSolidTeacup(2.5));
    SHOW("wire_teacup_1", glutWireTeacup(1.0));
    SHOW("solid_teaspoon_1", glutSolidTeaspoon(1.0));
    SHOW("wire_teaspoon_0.8", glutWireTeaspoon(0.8));
    SHOW("wire_teaspoon_1.7", glutWireTeaspoon(1.7));
    exit(0);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DEPTH);
    glutCreateWindow("shapes");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
