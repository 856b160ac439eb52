/* Provokes GLU NURBS errors with the real GLU (through OSMesa) and prints, per scenario, the
   error numbers the error callback received (n for GLU_NURBS_ERRORn, or the raw GLU code).
   The Rust test tests/it/glu_errors.rs runs the same scenarios on gleval and compares.
   Build: cc nurbs_errors.c -lOSMesa -lGLU -lGL */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>

static void errcb(GLenum e) {
    if (e >= GLU_NURBS_ERROR1 && e <= GLU_NURBS_ERROR37) printf(" %u", e - GLU_NURBS_ERROR1 + 1);
    else printf(" 0x%x", e);
}

static GLUnurbs *fresh(void) {
    GLUnurbs *n = gluNewNurbsRenderer();
    gluNurbsCallback(n, GLU_NURBS_ERROR, (void (*)(void))errcb);
    return n;
}

static GLfloat knots8[8] = {0, 0, 0, 0, 1, 1, 1, 1};
static GLfloat ctl[64 * 4];
static GLfloat trim_sq[5][2] = {{0.2f, 0.2f}, {0.8f, 0.2f}, {0.8f, 0.8f}, {0.2f, 0.8f}, {0.2f, 0.2f}};

#define SCENARIO(name) printf("%s:", name); n = fresh();
#define DONE gluDeleteNurbsRenderer(n); printf("\n");

static void surface(GLUnurbs *n) {
    gluNurbsSurface(n, 8, knots8, 8, knots8, 12, 3, ctl, 4, 4, GL_MAP2_VERTEX_3);
}

int main(void) {
    static GLubyte buf[64 * 64 * 4];
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64);
    for (int i = 0; i < 64 * 4; i++) ctl[i] = (GLfloat)((i * 7) % 5) * 0.1f;
    GLUnurbs *n;
    GLfloat bad_order_knots[2] = {0, 1};
    GLfloat empty_range[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    GLfloat decreasing[8] = {0, 0, 0, 1, 0.5f, 1, 1, 1};
    GLfloat multiplicity[9] = {0, 0, 0, 0, 0, 1, 1, 1, 1};

    SCENARIO("order_0") gluNurbsCurve(n, 2, bad_order_knots, 3, ctl, 0, GL_MAP1_VERTEX_3); DONE
    SCENARIO("order_25") gluNurbsCurve(n, 8, knots8, 3, ctl, 25, GL_MAP1_VERTEX_3); DONE
    SCENARIO("too_few_knots") gluNurbsCurve(n, 7, knots8, 3, ctl, 4, GL_MAP1_VERTEX_3); DONE
    SCENARIO("empty_range") gluNurbsCurve(n, 8, empty_range, 3, ctl, 4, GL_MAP1_VERTEX_3); DONE
    SCENARIO("decreasing") gluNurbsCurve(n, 8, decreasing, 3, ctl, 4, GL_MAP1_VERTEX_3); DONE
    SCENARIO("multiplicity") gluNurbsCurve(n, 9, multiplicity, 3, ctl, 4, GL_MAP1_VERTEX_3); DONE
    SCENARIO("unknown_type") gluNurbsCurve(n, 8, knots8, 3, ctl, 4, GL_FILL); DONE
    SCENARIO("null_control") gluNurbsCurve(n, 8, knots8, 3, NULL, 4, GL_MAP1_VERTEX_3); DONE
    SCENARIO("negative_stride") gluNurbsCurve(n, 8, knots8, -3, ctl, 4, GL_MAP1_VERTEX_3); DONE
    SCENARIO("begin_curve_twice") gluBeginCurve(n); gluBeginCurve(n); gluEndCurve(n); DONE
    SCENARIO("end_curve_alone") gluEndCurve(n); DONE
    SCENARIO("begin_surface_twice") gluBeginSurface(n); gluBeginSurface(n); gluEndSurface(n); DONE
    SCENARIO("end_surface_alone") gluEndSurface(n); DONE
    SCENARIO("end_surface_in_trim") gluBeginSurface(n); surface(n); gluBeginTrim(n);
        gluPwlCurve(n, 5, &trim_sq[0][0], 2, GLU_MAP1_TRIM_2); gluEndSurface(n); DONE
    SCENARIO("trim_outside_surface") gluBeginTrim(n); gluPwlCurve(n, 5, &trim_sq[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(n); surface(n); gluEndSurface(n); DONE
    SCENARIO("trim_in_trim") gluBeginSurface(n); surface(n); gluBeginTrim(n); gluBeginTrim(n);
        gluPwlCurve(n, 5, &trim_sq[0][0], 2, GLU_MAP1_TRIM_2); gluEndTrim(n); gluEndSurface(n); DONE
    SCENARIO("end_trim_alone") gluBeginSurface(n); surface(n); gluEndTrim(n); gluEndSurface(n); DONE
    SCENARIO("empty_trim") gluBeginSurface(n); surface(n); gluBeginTrim(n); gluEndTrim(n); gluEndSurface(n); DONE
    SCENARIO("pwl_outside_trim") gluBeginSurface(n); surface(n); gluPwlCurve(n, 5, &trim_sq[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndSurface(n); DONE
    SCENARIO("pwl_wrong_type") gluBeginSurface(n); surface(n); gluBeginTrim(n);
        gluPwlCurve(n, 5, &trim_sq[0][0], 2, GL_MAP1_VERTEX_3); gluEndTrim(n); gluEndSurface(n); DONE
    SCENARIO("pwl_negative_count") gluBeginSurface(n); surface(n); gluBeginTrim(n);
        gluPwlCurve(n, -1, &trim_sq[0][0], 2, GLU_MAP1_TRIM_2); gluEndTrim(n); gluEndSurface(n); DONE
    SCENARIO("pwl_negative_stride") gluBeginSurface(n); surface(n); gluBeginTrim(n);
        gluPwlCurve(n, 5, &trim_sq[0][0], -2, GLU_MAP1_TRIM_2); gluEndTrim(n); gluEndSurface(n); DONE
    SCENARIO("pwl_unknown_type") gluBeginSurface(n); surface(n); gluBeginTrim(n);
        gluPwlCurve(n, 5, &trim_sq[0][0], 2, GL_FILL); gluEndTrim(n); gluEndSurface(n); DONE
    SCENARIO("bad_property") gluNurbsProperty(n, 12345, 1.0f); DONE
    SCENARIO("bad_display_mode") gluNurbsProperty(n, GLU_DISPLAY_MODE, 7.0f); DONE
    SCENARIO("bad_sampling_method") gluNurbsProperty(n, GLU_SAMPLING_METHOD, 7.0f); DONE
    SCENARIO("bad_nurbs_mode") gluNurbsProperty(n, GLU_NURBS_MODE, 7.0f); DONE
    SCENARIO("bad_get_property") { GLfloat v; gluGetNurbsProperty(n, 12345, &v); } DONE
    SCENARIO("bad_callback") gluNurbsCallback(n, 12345, (void (*)(void))errcb); DONE
    SCENARIO("valid_surface") gluBeginSurface(n); surface(n); gluEndSurface(n); DONE
    /* Knots closer than GLU's 1e-5 count as equal: five "equal" knots for order 4. */
    GLfloat near_equal[9] = {0, 2e-6f, 4e-6f, 6e-6f, 8e-6f, 1, 1, 1, 1};
    GLfloat apart[9] = {0, 0, 0, 0, 2e-5f, 1, 1, 1, 1};
    GLfloat negative[8] = {-3, -3, -3, -3, -1, -1, -1, -1};
    GLfloat tiny[8] = {0, 0, 0, 0, 1e-4f, 1e-4f, 1e-4f, 1e-4f};
    GLfloat huge[8] = {0, 0, 0, 0, 1e8f, 1e8f, 1e8f, 1e8f};
    SCENARIO("near_equal_knots") gluNurbsCurve(n, 9, near_equal, 3, ctl, 4, GL_MAP1_VERTEX_3); DONE
    SCENARIO("knots_just_apart") gluBeginCurve(n); gluNurbsCurve(n, 9, apart, 3, ctl, 4, GL_MAP1_VERTEX_3); gluEndCurve(n); DONE
    SCENARIO("negative_knots") gluBeginCurve(n); gluNurbsCurve(n, 8, negative, 3, ctl, 4, GL_MAP1_VERTEX_3); gluEndCurve(n); DONE
    SCENARIO("tiny_domain") gluBeginCurve(n); gluNurbsCurve(n, 8, tiny, 3, ctl, 4, GL_MAP1_VERTEX_3); gluEndCurve(n); DONE
    SCENARIO("huge_domain") gluBeginCurve(n); gluNurbsCurve(n, 8, huge, 3, ctl, 4, GL_MAP1_VERTEX_3); gluEndCurve(n); DONE
    SCENARIO("trim_begins_surface_then_ends") gluBeginTrim(n); gluEndTrim(n); gluEndCurve(n); gluEndSurface(n); DONE
    OSMesaDestroyContext(c);
    return 0;
}
