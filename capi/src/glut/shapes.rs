//! GLUT's solids (sphere, cube, cone, torus, the Platonic solids) and freeglut's (cylinder,
//! rhombic dodecahedron, Sierpinski sponge, teacup, teaspoon), solid and wire.

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

forward! {
    glutSolidTetrahedron() => glut_solid_tetrahedron;
    glutWireTetrahedron() => glut_wire_tetrahedron;
    glutSolidOctahedron() => glut_solid_octahedron;
    glutWireOctahedron() => glut_wire_octahedron;
    glutSolidDodecahedron() => glut_solid_dodecahedron;
    glutWireDodecahedron() => glut_wire_dodecahedron;
    glutSolidIcosahedron() => glut_solid_icosahedron;
    glutWireIcosahedron() => glut_wire_icosahedron;
    glutSolidRhombicDodecahedron() => glut_solid_rhombic_dodecahedron;
    glutWireRhombicDodecahedron() => glut_wire_rhombic_dodecahedron;
    glutSolidCylinder(radius: f64, height: f64, slices: i32, stacks: i32) => glut_solid_cylinder;
    glutWireCylinder(radius: f64, height: f64, slices: i32, stacks: i32) => glut_wire_cylinder;
    glutSolidTeacup(size: f64) => glut_solid_teacup;
    glutWireTeacup(size: f64) => glut_wire_teacup;
    glutSolidTeaspoon(size: f64) => glut_solid_teaspoon;
    glutWireTeaspoon(size: f64) => glut_wire_teaspoon;
}

/// The sponge's offset as C passes it (NULL: the origin).
///
/// # Safety
/// `offset` is NULL or points at three doubles.
unsafe fn offset3(offset: *const f64) -> [f64; 3] {
    if offset.is_null() {
        return [0.0; 3];
    }
    unsafe { [*offset, *offset.add(1), *offset.add(2)] }
}

entry! {
    /// `glutSolidSierpinskiSponge(levels, offset, scale)` (freeglut).
    unsafe fn glutSolidSierpinskiSponge(levels: i32, offset: *const f64, scale: f64) {
        let offset = unsafe { offset3(offset) };
        crate::context::with_gl(|gl| gl.glut_solid_sierpinski_sponge(levels, &offset, scale))
    }
}

entry! {
    /// `glutWireSierpinskiSponge(levels, offset, scale)` (freeglut).
    unsafe fn glutWireSierpinskiSponge(levels: i32, offset: *const f64, scale: f64) {
        let offset = unsafe { offset3(offset) };
        crate::context::with_gl(|gl| gl.glut_wire_sierpinski_sponge(levels, &offset, scale))
    }
}
