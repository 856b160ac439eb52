//! GLUT's solids: sphere, cube, cone and torus, solid and wire (`Gl::glut_solid_*`).

forward! {
    glutSolidSphere(radius: f64, slices: i32, stacks: i32) => glut_solid_sphere;
    glutWireSphere(radius: f64, slices: i32, stacks: i32) => glut_wire_sphere;
    glutSolidCube(size: f64) => glut_solid_cube;
    glutWireCube(size: f64) => glut_wire_cube;
    glutSolidCone(base: f64, height: f64, slices: i32, stacks: i32) => glut_solid_cone;
    glutWireCone(base: f64, height: f64, slices: i32, stacks: i32) => glut_wire_cone;
    glutSolidTorus(inner: f64, outer: f64, sides: i32, rings: i32) => glut_solid_torus;
    glutWireTorus(inner: f64, outer: f64, sides: i32, rings: i32) => glut_wire_torus;
}
