/* queries.inc.c - the state queries and parameter forms (issue 26), included by interp.c:
 *   get PNAME                     glGetBooleanv, glGetIntegerv, glGetFloatv, glGetDoublev;
 *                                 prints " b <values> i <values> f <values> d <values>"
 *   call NAME ARGS...             a GL call by its C name (table `calls` below); array
 *                                 arguments as [ v ... ] or null
 *   getv NAME ARGS...             a GL query that writes through a pointer; prints the values
 *   get_tex_image T LEVEL FORMAT TYPE, get_polygon_stipple
 *                                 print the bytes written, in hex
 * How many values a query wrote is measured, not assumed: the buffer is filled with one
 * pattern, then another, and the count is one past the last element either call changed. */

static const char *next(void);
static GLint arg_int(void);
static double arg_double(void);
static void val(const char *fmt, ...);
static void die(const char *msg, const char *what);

#define Q(x) { #x, x }
static const struct enum_name query_enums[] = {
    Q(GL_CURRENT_INDEX), Q(GL_CURRENT_RASTER_INDEX), Q(GL_EDGE_FLAG), Q(GL_MODELVIEW_MATRIX),
    Q(GL_PROJECTION_MATRIX), Q(GL_TEXTURE_MATRIX), Q(GL_VIEWPORT), Q(GL_DEPTH_RANGE),
    Q(GL_TRANSPOSE_MODELVIEW_MATRIX), Q(GL_TRANSPOSE_PROJECTION_MATRIX), Q(GL_TRANSPOSE_TEXTURE_MATRIX),
    Q(GL_MAX_ELEMENTS_VERTICES), Q(GL_MAX_ELEMENTS_INDICES),
    Q(GL_BLEND_SRC_RGB), Q(GL_BLEND_DST_RGB), Q(GL_BLEND_SRC_ALPHA), Q(GL_BLEND_DST_ALPHA),
    Q(GL_BLEND_EQUATION), Q(GL_BLEND_EQUATION_ALPHA), Q(GL_BLEND_COLOR), Q(GL_FUNC_ADD),
    Q(GL_FUNC_SUBTRACT), Q(GL_FUNC_REVERSE_SUBTRACT), Q(GL_MIN), Q(GL_MAX), Q(GL_CONSTANT_COLOR),
    Q(GL_ONE_MINUS_CONSTANT_COLOR), Q(GL_CONSTANT_ALPHA), Q(GL_ONE_MINUS_CONSTANT_ALPHA),
    Q(GL_SRC_COLOR), Q(GL_ONE_MINUS_SRC_COLOR), Q(GL_DST_ALPHA), Q(GL_ONE_MINUS_DST_ALPHA),
    Q(GL_DST_COLOR), Q(GL_ONE_MINUS_DST_COLOR),
    Q(GL_MULTISAMPLE), Q(GL_SAMPLE_ALPHA_TO_COVERAGE), Q(GL_SAMPLE_ALPHA_TO_ONE),
    Q(GL_SAMPLE_COVERAGE), Q(GL_SAMPLE_COVERAGE_VALUE), Q(GL_SAMPLE_COVERAGE_INVERT),
    Q(GL_SAMPLE_BUFFERS), Q(GL_SAMPLES), Q(GL_MULTISAMPLE_BIT),
    Q(GL_COLOR_SUM), Q(GL_CURRENT_SECONDARY_COLOR), Q(GL_LIGHT_MODEL_COLOR_CONTROL), Q(GL_SINGLE_COLOR),
    Q(GL_SEPARATE_SPECULAR_COLOR), Q(GL_SECONDARY_COLOR_ARRAY), Q(GL_SECONDARY_COLOR_ARRAY_SIZE),
    Q(GL_SECONDARY_COLOR_ARRAY_TYPE), Q(GL_SECONDARY_COLOR_ARRAY_STRIDE), Q(GL_SECONDARY_COLOR_ARRAY_POINTER),
    Q(GL_TEXTURE_BASE_LEVEL), Q(GL_TEXTURE_MAX_LEVEL), Q(GL_TEXTURE_MIN_LOD), Q(GL_TEXTURE_MAX_LOD),
    Q(GL_MODELVIEW_STACK_DEPTH), Q(GL_PROJECTION_STACK_DEPTH), Q(GL_TEXTURE_STACK_DEPTH),
    Q(GL_MATRIX_MODE), Q(GL_MODELVIEW), Q(GL_PROJECTION), Q(GL_TEXTURE), Q(GL_FOG_COLOR),
    Q(GL_FOG_INDEX), Q(GL_SHADE_MODEL), Q(GL_FLAT), Q(GL_SMOOTH), Q(GL_COLOR_MATERIAL),
    Q(GL_COLOR_MATERIAL_PARAMETER), Q(GL_COLOR_MATERIAL_FACE), Q(GL_LIGHT_MODEL_AMBIENT),
    Q(GL_LIGHT_MODEL_LOCAL_VIEWER), Q(GL_LIGHT_MODEL_TWO_SIDE), Q(GL_POINT_SIZE), Q(GL_LINE_WIDTH),
    Q(GL_CULL_FACE_MODE), Q(GL_FRONT_FACE), Q(GL_POLYGON_MODE), Q(GL_POLYGON_SMOOTH),
    Q(GL_ACTIVE_TEXTURE), Q(GL_SCISSOR_BOX), Q(GL_SCISSOR_TEST), Q(GL_ALPHA_TEST_FUNC),
    Q(GL_ALPHA_TEST_REF), Q(GL_STENCIL_TEST), Q(GL_DEPTH_FUNC), Q(GL_BLEND_SRC), Q(GL_BLEND_DST),
    Q(GL_DITHER), Q(GL_INDEX_LOGIC_OP), Q(GL_COLOR_LOGIC_OP), Q(GL_DRAW_BUFFER),
    Q(GL_COLOR_CLEAR_VALUE), Q(GL_DEPTH_CLEAR_VALUE), Q(GL_UNPACK_SWAP_BYTES),
    Q(GL_UNPACK_SKIP_PIXELS), Q(GL_PACK_SWAP_BYTES), Q(GL_PACK_LSB_FIRST), Q(GL_PACK_ROW_LENGTH),
    Q(GL_PACK_SKIP_ROWS), Q(GL_PACK_SKIP_PIXELS), Q(GL_MAX_LIGHTS), Q(GL_MAX_MODELVIEW_STACK_DEPTH),
    Q(GL_MAX_PROJECTION_STACK_DEPTH), Q(GL_MAX_TEXTURE_STACK_DEPTH), Q(GL_SUBPIXEL_BITS),
    Q(GL_MAX_TEXTURE_SIZE), Q(GL_MAX_PIXEL_MAP_TABLE), Q(GL_MAX_NAME_STACK_DEPTH),
    Q(GL_MAX_VIEWPORT_DIMS), Q(GL_MAX_ATTRIB_STACK_DEPTH), Q(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH),
    Q(GL_AUX_BUFFERS), Q(GL_RGBA_MODE), Q(GL_INDEX_MODE), Q(GL_STEREO), Q(GL_POINT_SIZE_RANGE),
    Q(GL_POINT_SIZE_GRANULARITY), Q(GL_LINE_WIDTH_RANGE), Q(GL_LINE_WIDTH_GRANULARITY),
    Q(GL_ALIASED_POINT_SIZE_RANGE), Q(GL_ALIASED_LINE_WIDTH_RANGE), Q(GL_RED_BITS),
    Q(GL_GREEN_BITS), Q(GL_BLUE_BITS), Q(GL_ALPHA_BITS), Q(GL_INDEX_BITS), Q(GL_DEPTH_BITS),
    Q(GL_ATTRIB_STACK_DEPTH), Q(GL_CLIENT_ATTRIB_STACK_DEPTH), Q(GL_RENDER_MODE),
    Q(GL_FEEDBACK_BUFFER_SIZE), Q(GL_FEEDBACK_BUFFER_TYPE), Q(GL_RESCALE_NORMAL), Q(GL_MULTISAMPLE),
    Q(GL_VERTEX_ARRAY), Q(GL_NORMAL_ARRAY), Q(GL_COLOR_ARRAY), Q(GL_INDEX_ARRAY),
    Q(GL_TEXTURE_COORD_ARRAY), Q(GL_EDGE_FLAG_ARRAY), Q(GL_LIGHT0), Q(GL_LIGHT1), Q(GL_LIGHT2), Q(GL_LIGHT3), Q(GL_LIGHT4), Q(GL_LIGHT5), Q(GL_LIGHT6), Q(GL_LIGHT7),
    Q(GL_TEXTURE_GEN_R), Q(GL_AMBIENT), Q(GL_SPECULAR), Q(GL_POSITION), Q(GL_SPOT_DIRECTION),
    Q(GL_SPOT_EXPONENT), Q(GL_SPOT_CUTOFF), Q(GL_CONSTANT_ATTENUATION), Q(GL_LINEAR_ATTENUATION),
    Q(GL_QUADRATIC_ATTENUATION), Q(GL_EMISSION), Q(GL_AMBIENT_AND_DIFFUSE), Q(GL_COLOR_INDEXES),
    Q(GL_BACK), Q(GL_FRONT_AND_BACK), Q(GL_TEXTURE_BORDER_COLOR), Q(GL_TEXTURE_PRIORITY),
    Q(GL_TEXTURE_RESIDENT), Q(GL_TEXTURE_WIDTH), Q(GL_TEXTURE_HEIGHT), Q(GL_TEXTURE_BORDER),
    Q(GL_TEXTURE_INTERNAL_FORMAT), Q(GL_TEXTURE_RED_SIZE), Q(GL_TEXTURE_GREEN_SIZE),
    Q(GL_TEXTURE_BLUE_SIZE), Q(GL_TEXTURE_ALPHA_SIZE), Q(GL_TEXTURE_LUMINANCE_SIZE),
    Q(GL_TEXTURE_INTENSITY_SIZE), Q(GL_LINEAR_MIPMAP_NEAREST), Q(GL_NEAREST_MIPMAP_LINEAR),
    Q(GL_RGB8), Q(GL_RGBA8), Q(GL_LUMINANCE8), Q(GL_ALPHA8), Q(GL_CW), Q(GL_CCW), Q(GL_LESS),
    Q(GL_LEQUAL), Q(GL_LINEAR), Q(GL_UNPACK_SKIP_ROWS), Q(GL_CLIENT_PIXEL_STORE_BIT),
    Q(GL_VIEWPORT_BIT), Q(GL_FOG_BIT), Q(GL_POINT_BIT), Q(GL_DEPTH_BUFFER_BIT),
    Q(GL_COLOR_BUFFER_BIT), Q(GL_LIST_BIT), Q(GL_SCISSOR_BIT), Q(GL_STENCIL_BUFFER_BIT),
    Q(GL_PIXEL_MODE_BIT), Q(GL_ACCUM_BUFFER_BIT), Q(GL_DEPTH_WRITEMASK), Q(GL_COLOR_WRITEMASK),
    Q(GL_INDEX_CLEAR_VALUE), Q(GL_STENCIL_BITS), Q(GL_ACCUM_RED_BITS), Q(GL_DOUBLEBUFFER),
    Q(GL_READ_BUFFER), Q(GL_ZOOM_X), Q(GL_RED_SCALE), Q(GL_MAP_COLOR), Q(GL_NAME_STACK_DEPTH),
    Q(GL_SELECTION_BUFFER_SIZE), Q(GL_VERTEX_ARRAY_SIZE), Q(GL_LOGIC_OP_MODE),
    Q(GL_STENCIL_FUNC), Q(GL_PIXEL_MAP_I_TO_I_SIZE), Q(GL_ACCUM_CLEAR_VALUE), Q(GL_INTENSITY),
    Q(GL_PROXY_TEXTURE_2D), Q(GL_EXP), Q(GL_FEEDBACK), Q(GL_RENDER), Q(GL_3D), Q(GL_2D),
    Q(GL_FOG_MODE), Q(GL_EYE_LINEAR),
    Q(GL_TEXTURE_3D), Q(GL_PROXY_TEXTURE_3D), Q(GL_TEXTURE_BINDING_3D), Q(GL_MAX_3D_TEXTURE_SIZE),
    Q(GL_TEXTURE_DEPTH), Q(GL_TEXTURE_WRAP_R), Q(GL_UNPACK_SKIP_IMAGES), Q(GL_UNPACK_IMAGE_HEIGHT),
    Q(GL_PACK_SKIP_IMAGES), Q(GL_PACK_IMAGE_HEIGHT), Q(GL_PROXY_TEXTURE_1D),
    Q(GL_COMBINE), Q(GL_COMBINE_RGB), Q(GL_COMBINE_ALPHA), Q(GL_SOURCE0_RGB), Q(GL_SOURCE1_RGB),
    Q(GL_SOURCE2_RGB), Q(GL_SOURCE0_ALPHA), Q(GL_SOURCE1_ALPHA), Q(GL_SOURCE2_ALPHA), Q(GL_OPERAND0_RGB),
    Q(GL_OPERAND1_RGB), Q(GL_OPERAND2_RGB), Q(GL_OPERAND0_ALPHA), Q(GL_OPERAND1_ALPHA), Q(GL_OPERAND2_ALPHA),
    Q(GL_RGB_SCALE), Q(GL_ALPHA_SCALE), Q(GL_ADD_SIGNED), Q(GL_INTERPOLATE), Q(GL_SUBTRACT), Q(GL_CONSTANT),
    Q(GL_PRIMARY_COLOR), Q(GL_PREVIOUS), Q(GL_DOT3_RGB), Q(GL_DOT3_RGBA), Q(GL_SRC_ALPHA),
    Q(GL_CLAMP_TO_BORDER), Q(GL_MIRRORED_REPEAT), Q(GL_GENERATE_MIPMAP), Q(GL_GENERATE_MIPMAP_HINT),
    Q(GL_ONE_MINUS_SRC_ALPHA), Q(GL_TEXTURE0), Q(GL_TEXTURE1), Q(GL_TEXTURE7), Q(GL_TEXTURE8),
    Q(GL_CLIENT_ACTIVE_TEXTURE), Q(GL_MAX_TEXTURE_UNITS),
    Q(GL_UNSIGNED_BYTE_2_3_3_REV), Q(GL_UNSIGNED_SHORT_5_6_5_REV), Q(GL_UNSIGNED_SHORT_4_4_4_4_REV),
    Q(GL_UNSIGNED_SHORT_5_5_5_1), Q(GL_UNSIGNED_SHORT_1_5_5_5_REV), Q(GL_UNSIGNED_INT_8_8_8_8),
    Q(GL_UNSIGNED_INT_10_10_10_2), Q(GL_UNSIGNED_INT_2_10_10_10_REV), Q(GL_RED_BIAS),
    Q(GL_GREEN_BIAS), Q(GL_BLUE_BIAS), Q(GL_ALPHA_BIAS), Q(GL_GREEN_SCALE),
    Q(GL_POINT_SIZE_MIN), Q(GL_POINT_SIZE_MAX), Q(GL_POINT_FADE_THRESHOLD_SIZE), Q(GL_POINT_DISTANCE_ATTENUATION),
    Q(GL_FOG_COORD_SRC), Q(GL_FOG_COORD), Q(GL_FRAGMENT_DEPTH), Q(GL_CURRENT_FOG_COORD), Q(GL_FOG_COORD_ARRAY),
    Q(GL_FOG_COORD_ARRAY_TYPE), Q(GL_FOG_COORD_ARRAY_STRIDE), Q(GL_FOG_COORD_ARRAY_POINTER),
    Q(GL_COMPRESSED_ALPHA), Q(GL_COMPRESSED_LUMINANCE), Q(GL_COMPRESSED_LUMINANCE_ALPHA), Q(GL_COMPRESSED_INTENSITY),
    Q(GL_COMPRESSED_RGB), Q(GL_COMPRESSED_RGBA), Q(GL_TEXTURE_COMPRESSION_HINT), Q(GL_TEXTURE_COMPRESSED_IMAGE_SIZE),
    Q(GL_TEXTURE_COMPRESSED), Q(GL_NUM_COMPRESSED_TEXTURE_FORMATS), Q(GL_COMPRESSED_TEXTURE_FORMATS),
    Q(GL_TEXTURE_FILTER_CONTROL), Q(GL_TEXTURE_LOD_BIAS), Q(GL_MAX_TEXTURE_LOD_BIAS),
    Q(GL_TEXTURE_CUBE_MAP), Q(GL_TEXTURE_BINDING_CUBE_MAP), Q(GL_TEXTURE_CUBE_MAP_POSITIVE_X),
    Q(GL_TEXTURE_CUBE_MAP_NEGATIVE_X), Q(GL_TEXTURE_CUBE_MAP_POSITIVE_Y), Q(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y),
    Q(GL_TEXTURE_CUBE_MAP_POSITIVE_Z), Q(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z), Q(GL_PROXY_TEXTURE_CUBE_MAP),
    Q(GL_MAX_CUBE_MAP_TEXTURE_SIZE), Q(GL_CLAMP_TO_EDGE),
    Q(GL_DEPTH_TEXTURE_MODE), Q(GL_TEXTURE_COMPARE_MODE), Q(GL_TEXTURE_COMPARE_FUNC),
    Q(GL_COMPARE_R_TO_TEXTURE), Q(GL_DEPTH_COMPONENT16), Q(GL_DEPTH_COMPONENT24), Q(GL_DEPTH_COMPONENT32),
    Q(GL_TEXTURE_DEPTH_SIZE), Q(GL_RED), Q(GL_NEVER), Q(GL_NOTEQUAL), Q(GL_ALWAYS), Q(GL_NONE),
    Q(GL_DEPTH_STENCIL), Q(GL_UNSIGNED_INT_24_8), Q(GL_DEPTH24_STENCIL8), Q(GL_STENCIL_INDEX), Q(GL_INT),
    Q(GL_POINT_SPRITE), Q(GL_COORD_REPLACE), Q(GL_MODULATE), Q(GL_TEXTURE_STENCIL_SIZE),
    Q(GL_HISTOGRAM), Q(GL_PROXY_HISTOGRAM), Q(GL_MINMAX), Q(GL_COLOR_TABLE), Q(GL_CONVOLUTION_1D),
    Q(GL_CONVOLUTION_2D), Q(GL_SEPARABLE_2D), Q(GL_POST_CONVOLUTION_COLOR_TABLE),
    Q(GL_POST_COLOR_MATRIX_COLOR_TABLE), Q(GL_CONVOLUTION_BORDER_MODE), Q(GL_REDUCE),
    Q(GL_CONVOLUTION_FILTER_SCALE), Q(GL_COLOR_TABLE_BIAS), Q(GL_COLOR_TABLE_SCALE), Q(GL_HISTOGRAM_WIDTH),
    Q(GL_MINMAX_FORMAT), Q(GL_MAX_COLOR_MATRIX_STACK_DEPTH), Q(GL_POST_CONVOLUTION_RED_SCALE),
    { NULL, 0 }
};

static int query_enum(const char *s, GLenum *v)
{
    for (int i = 0; query_enums[i].name; i++)
        if (strcmp(query_enums[i].name, s) == 0) { *v = query_enums[i].value; return 1; }
    return 0;
}

/* ---------------------------------------------------------------- arrays of any type */
#define QMAX 64
union qarray { GLfloat f[QMAX]; GLint i[QMAX]; GLdouble d[QMAX]; };

/* `[ v ... ]` into `a` as type t ('f', 'i', 'd'); returns NULL for `null`. */
static void *q_array(char t, union qarray *a)
{
    const char *s = next();
    memset(a, 0, sizeof *a);
    if (strcmp(s, "null") == 0) return NULL;
    if (strcmp(s, "[") != 0) die("expected [", s);
    for (int n = 0; strcmp(tok[pos], "]") != 0; n++) {
        if (n == QMAX) die("array too long", NULL);
        if (t == 'i') a->i[n] = arg_int();
        else if (t == 'd') a->d[n] = arg_double();
        else a->f[n] = (GLfloat)arg_double();
    }
    pos++;
    return a;
}

/* ---------------------------------------------------------------- measured writes */
/* Calls `q` twice on a buffer of `size` bytes filled with 0xA5 then 0x5A; returns how many
 * elements of `elem` bytes it wrote (one past the last changed in either run), with the
 * second run's values in `out`. */
static int measured(void (*q)(void *, void *), void *ctx, unsigned char *out, size_t size, size_t elem)
{
    unsigned char first[QMAX * 8 + 512];
    memset(first, 0xA5, size);
    q(ctx, first);
    memset(out, 0x5A, size);
    q(ctx, out);
    size_t last = 0;
    for (size_t b = 0; b < size; b++)
        if (first[b] != 0xA5 || out[b] != 0x5A) last = b / elem + 1;
    return (int)last;
}

static GLenum get_pname;
static void q_getb(void *c, void *o) { (void)c; glGetBooleanv(get_pname, o); }
static void q_geti(void *c, void *o) { (void)c; glGetIntegerv(get_pname, o); }
static void q_getf(void *c, void *o) { (void)c; glGetFloatv(get_pname, o); }
static void q_getd(void *c, void *o) { (void)c; glGetDoublev(get_pname, o); }

static void print_values(char t, const void *p, int n)
{
    for (int k = 0; k < n; k++) {
        if (t == 'b') val(" %d", ((const GLboolean *)p)[k]);
        else if (t == 'i') val(" %d", ((const GLint *)p)[k]);
        else if (t == 'f') val(" %.9g", ((const GLfloat *)p)[k]);
        else val(" %.9g", ((const GLdouble *)p)[k]);
    }
}

static void run_get(void)
{
    unsigned char out[QMAX * 8];
    get_pname = arg_enum();
    static const struct { char t; void (*q)(void *, void *); size_t elem; } kinds[] = {
        { 'b', q_getb, sizeof(GLboolean) }, { 'i', q_geti, sizeof(GLint) },
        { 'f', q_getf, sizeof(GLfloat) }, { 'd', q_getd, sizeof(GLdouble) },
    };
    for (int k = 0; k < 4; k++) {
        int n = measured(kinds[k].q, NULL, out, 32 * kinds[k].elem, kinds[k].elem);
        val(" %c", kinds[k].t);
        print_values(kinds[k].t, out, n);
    }
}

/* ---------------------------------------------------------------- calls by name */
typedef void (*fn_ptr)(void);
struct qcall { const char *name; const char *sig; fn_ptr fn; };
#define C(name, sig) { #name, sig, (fn_ptr)name }
/* Signatures: e enum, i int, f float, d double; F, I, D an array of them; a leading '>'
 * marks the getters (`getv`), whose last argument is the array written. */
static const struct qcall calls[] = {
    C(glLightf, "eef"), C(glLighti, "eei"), C(glLightfv, "eeF"), C(glLightiv, "eeI"),
    C(glLightModelf, "ef"), C(glLightModeli, "ei"), C(glLightModelfv, "eF"), C(glLightModeliv, "eI"),
    C(glMaterialf, "eef"), C(glMateriali, "eei"), C(glMaterialfv, "eeF"), C(glMaterialiv, "eeI"),
    C(glFogf, "ef"), C(glFogi, "ee"), C(glFogfv, "eF"), C(glFogiv, "eI"),
    C(glTexEnvf, "eef"), C(glTexEnvi, "eee"), C(glTexEnvfv, "eeF"), C(glTexEnviv, "eeI"),
    C(glTexParameterf, "eef"), C(glTexParameteri, "eee"), C(glTexParameterfv, "eeF"),
    C(glTexParameteriv, "eeI"), C(glTexGend, "eed"), C(glTexGenf, "eef"), C(glTexGeni, "eee"),
    C(glTexGendv, "eeD"), C(glTexGeniv, "eeI"), C(glColorMaterial, "ee"), C(glShadeModel, "e"),
    C(glMatrixMode, "e"), C(glPushMatrix, ""), C(glPopMatrix, ""), C(glViewport, "iiii"),
    C(glDepthRange, "dd"), C(glPointSize, "f"), C(glLineWidth, "f"), C(glFrontFace, "e"),
    C(glCullFace, "e"), C(glPolygonMode, "ee"), C(glDepthFunc, "e"), C(glClearColor, "ffff"),
    C(glClearDepth, "d"), C(glPushClientAttrib, "e"), C(glPopClientAttrib, ""),
    C(glPixelStorei, "ei"), C(glPixelStoref, "ef"), C(glFrustum, "dddddd"), C(glOrtho, "dddddd"),
    C(glColor4f, "ffff"), C(glNormal3f, "fff"), C(glEnable, "e"), C(glDisable, "e"),
    C(glFeedbackBuffer, "ie-"), C(glRenderMode, "e"), C(glBlendFunc, "ee"), C(glAlphaFunc, "ef"),
    C(glBlendFuncSeparate, "eeee"), C(glBlendEquation, "e"), C(glBlendEquationSeparate, "ee"),
    C(glBlendColor, "ffff"), C(glSampleCoverage, "fe"), C(glSecondaryColor3f, "fff"), C(glHint, "ee"),
    C(glTexImage1D, "eieiieeF"), C(glGetLightfv, ">eeF"), C(glGetLightiv, ">eeI"),
    C(glGetMaterialfv, ">eeF"), C(glGetMaterialiv, ">eeI"), C(glGetTexEnvfv, ">eeF"),
    C(glGetTexEnviv, ">eeI"), C(glGetTexParameterfv, ">eeF"), C(glGetTexParameteriv, ">eeI"),
    C(glGetTexLevelParameterfv, ">eieF"), C(glGetTexLevelParameteriv, ">eieI"),
    C(glGetTexGenfv, ">eeF"), C(glGetTexGeniv, ">eeI"), C(glGetTexGendv, ">eeD"),
    C(glGetClipPlane, ">eD"), C(glGetMapdv, ">eeD"),
    C(glPointParameterf, "ef"), C(glPointParameterfv, "eF"), C(glPointParameteri, "ei"),
    C(glPointParameteriv, "eI"),
    C(glFogCoordf, "f"), C(glFogCoordd, "d"), C(glFogCoordfv, "F"), C(glFogCoorddv, "D"),
    C(glCompressedTexImage1D, "eieiiiI"), C(glCompressedTexImage2D, "eieiiiiI"),
    C(glCompressedTexSubImage2D, "eiiiiieiI"), C(glGetCompressedTexImage, ">eiI"),
    C(glResetHistogram, "e"), C(glResetMinmax, "e"), C(glMinmax, "eee"), C(glHistogram, "eeee"),
    C(glConvolutionParameteri, "eee"), C(glConvolutionParameterf, "eef"),
    C(glConvolutionParameterfv, "eeF"), C(glColorTableParameteriv, "eeI"),
    C(glGetHistogramParameteriv, ">eeI"), C(glGetMinmaxParameterfv, ">eeF"),
    C(glGetConvolutionParameteriv, ">eeI"), C(glGetColorTableParameterfv, ">eeF"),
    C(glActiveTexture, "e"), C(glClientActiveTexture, "e"), C(glMultiTexCoord4f, "effff"),
    C(glMultiTexCoord2f, "eff"), C(glMultiTexCoord1d, "ed"), C(glMultiTexCoord3i, "eiii"),
    C(glMultiTexCoord4s, "eiiii"), C(glMultiTexCoord2fv, "eF"), C(glMultiTexCoord3dv, "eD"),
    C(glMultiTexCoord4iv, "eI"), C(glEnableClientState, "e"), C(glDisableClientState, "e"),
    C(glLoadIdentity, ""), C(glTranslatef, "fff"), C(glRasterPos2f, "ff"),
    { NULL, NULL, NULL }
};

/* The arguments of a call, by kind, in order. */
struct qargs { GLuint u[8]; int nu; GLfloat f[8]; int nf; GLdouble d[8]; int nd; void *p; union qarray a; };

static void read_args(const char *sig, struct qargs *x)
{
    memset(x, 0, sizeof *x);
    for (const char *s = sig; *s; s++) {
        switch (*s) {
        case 'e': x->u[x->nu++] = arg_enum(); break;
        case 'i': x->u[x->nu++] = (GLuint)arg_int(); break;
        case 'f': x->f[x->nf++] = (GLfloat)arg_double(); break;
        case 'd': x->d[x->nd++] = arg_double(); break;
        case 'F': x->p = q_array('f', &x->a); break;
        case 'I': x->p = q_array('i', &x->a); break;
        case 'D': x->p = q_array('d', &x->a); break;
        case '-': break;
        default: die("bad signature", sig);
        }
    }
}

/* Whether a signature is integers (e, i) then one array. */
static int integers_then_pointer(const char *sig)
{
    size_t n = strlen(sig);
    if (n < 2 || (sig[n - 1] != 'I' && sig[n - 1] != 'F')) return 0;
    for (size_t k = 0; k + 1 < n; k++)
        if (sig[k] != 'e' && sig[k] != 'i') return 0;
    return 1;
}

/* Calls fn with the arguments as the signature lays them out. Integers and enums share the
 * integer registers and floats and doubles the vector ones, so each shape needs one cast. */
static void invoke(const char *sig, fn_ptr fn, const struct qargs *x)
{
    const GLuint *u = x->u;
    const GLfloat *f = x->f;
    const GLdouble *d = x->d;
    void *p = x->p;
    if (!strcmp(sig, "") ) ((void (*)(void))fn)();
    else if (!strcmp(sig, "e")) ((void (*)(GLuint))fn)(u[0]);
    else if (!strcmp(sig, "ee") || !strcmp(sig, "ei")) ((void (*)(GLuint, GLuint))fn)(u[0], u[1]);
    else if (!strcmp(sig, "eei") || !strcmp(sig, "eee")) ((void (*)(GLuint, GLuint, GLuint))fn)(u[0], u[1], u[2]);
    else if (!strcmp(sig, "iiii") || !strcmp(sig, "eeee")) ((void (*)(GLuint, GLuint, GLuint, GLuint))fn)(u[0], u[1], u[2], u[3]);
    else if (!strcmp(sig, "f")) ((void (*)(GLfloat))fn)(f[0]);
    else if (!strcmp(sig, "ef")) ((void (*)(GLuint, GLfloat))fn)(u[0], f[0]);
    else if (!strcmp(sig, "fe")) ((void (*)(GLfloat, GLuint))fn)(f[0], u[0]);
    else if (!strcmp(sig, "eff")) ((void (*)(GLuint, GLfloat, GLfloat))fn)(u[0], f[0], f[1]);
    else if (!strcmp(sig, "ff")) ((void (*)(GLfloat, GLfloat))fn)(f[0], f[1]);
    else if (!strcmp(sig, "effff"))
        ((void (*)(GLuint, GLfloat, GLfloat, GLfloat, GLfloat))fn)(u[0], f[0], f[1], f[2], f[3]);
    else if (!strcmp(sig, "ed")) ((void (*)(GLuint, GLdouble))fn)(u[0], d[0]);
    else if (!strcmp(sig, "eiii")) ((void (*)(GLuint, GLuint, GLuint, GLuint))fn)(u[0], u[1], u[2], u[3]);
    else if (!strcmp(sig, "eiiii"))
        ((void (*)(GLuint, GLuint, GLuint, GLuint, GLuint))fn)(u[0], u[1], u[2], u[3], u[4]);
    else if (!strcmp(sig, "eef")) ((void (*)(GLuint, GLuint, GLfloat))fn)(u[0], u[1], f[0]);
    else if (!strcmp(sig, "fff")) ((void (*)(GLfloat, GLfloat, GLfloat))fn)(f[0], f[1], f[2]);
    else if (!strcmp(sig, "ffff")) ((void (*)(GLfloat, GLfloat, GLfloat, GLfloat))fn)(f[0], f[1], f[2], f[3]);
    else if (!strcmp(sig, "d")) ((void (*)(GLdouble))fn)(d[0]);
    else if (!strcmp(sig, "dd")) ((void (*)(GLdouble, GLdouble))fn)(d[0], d[1]);
    else if (!strcmp(sig, "eed")) ((void (*)(GLuint, GLuint, GLdouble))fn)(u[0], u[1], d[0]);
    else if (!strcmp(sig, "dddddd"))
        ((void (*)(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble))fn)(d[0], d[1], d[2], d[3], d[4], d[5]);
    else if (!strcmp(sig, "F") || !strcmp(sig, "I") || !strcmp(sig, "D")) ((void (*)(void *))fn)(p);
    else if (!strcmp(sig, "eF") || !strcmp(sig, "eI") || !strcmp(sig, "eD"))
        ((void (*)(GLuint, void *))fn)(u[0], p);
    else if (!strcmp(sig, "eeF") || !strcmp(sig, "eeI") || !strcmp(sig, "eeD"))
        ((void (*)(GLuint, GLuint, void *))fn)(u[0], u[1], p);
    else if (!strcmp(sig, "eieF") || !strcmp(sig, "eieI"))
        ((void (*)(GLuint, GLuint, GLuint, void *))fn)(u[0], u[1], u[2], p);
    else if (!strcmp(sig, "ie-")) {
        static GLfloat buffer[1 << 16];
        ((void (*)(GLuint, GLuint, void *))fn)(u[0], u[1], buffer);
    } else if (!strcmp(sig, "eieiieeF"))
        ((void (*)(GLuint, GLuint, GLuint, GLuint, GLuint, GLuint, GLuint, const void *))fn)(
            u[0], u[1], u[2], u[3], u[4], u[5], u[6], p);
    else if (integers_then_pointer(sig)) {
        /* n integers (enums, ints, sizes) and a trailing pointer: the compressed-image calls. */
        typedef GLuint U;
        switch (strlen(sig) - 1) {
        case 2: ((void (*)(U, U, void *))fn)(u[0], u[1], p); break;
        case 6: ((void (*)(U, U, U, U, U, U, void *))fn)(u[0], u[1], u[2], u[3], u[4], u[5], p); break;
        case 7: ((void (*)(U, U, U, U, U, U, U, void *))fn)(u[0], u[1], u[2], u[3], u[4], u[5], u[6], p); break;
        case 8: ((void (*)(U, U, U, U, U, U, U, U, void *))fn)(u[0], u[1], u[2], u[3], u[4], u[5], u[6], u[7], p); break;
        default: die("no call shape for", sig);
        }
    }
    else die("no call shape for", sig);
}

static const struct qcall *find_call(void)
{
    const char *name = next();
    for (const struct qcall *c = calls; c->name; c++)
        if (!strcmp(c->name, name)) return c;
    die("unknown call name", name);
    return NULL;
}

/* `getv NAME args`: the arguments before the written array, then the measured values. */
struct getv_ctx { const struct qcall *c; struct qargs x; char type; };
static void q_getv(void *vc, void *out)
{
    struct getv_ctx *g = vc;
    g->x.p = out;
    invoke(g->c->sig + 1, g->c->fn, &g->x);
}

static void run_getv(void)
{
    struct getv_ctx g;
    g.c = find_call();
    if (g.c->sig[0] != '>') die("not a query", g.c->name);
    size_t n = strlen(g.c->sig);
    char prefix[16];
    memcpy(prefix, g.c->sig + 1, n - 2);
    prefix[n - 2] = '\0';
    read_args(prefix, &g.x);
    char t = g.c->sig[n - 1];
    size_t elem = t == 'D' ? sizeof(GLdouble) : 4;
    unsigned char out[QMAX * 8];
    int count = measured(q_getv, &g, out, 16 * elem, elem);
    print_values(t == 'F' ? 'f' : t == 'I' ? 'i' : 'd', out, count);
}

static void print_bytes(const unsigned char *b, int n)
{
    if (n) val(" ");
    for (int k = 0; k < n; k++) val("%02x", b[k]);
}

static GLenum img_args[4];
static void q_teximage(void *c, void *o)
{
    (void)c;
    glGetTexImage(img_args[0], (GLint)img_args[1], img_args[2], img_args[3], o);
}
static void q_stipple(void *c, void *o) { (void)c; glGetPolygonStipple(o); }

static int run_queries_call(const char *c)
{
    if (!strcmp(c, "get")) {
        run_get();
    } else if (!strcmp(c, "call")) {
        const struct qcall *q = find_call();
        struct qargs x;
        read_args(q->sig, &x);
        invoke(q->sig, q->fn, &x);
    } else if (!strcmp(c, "getv")) {
        run_getv();
    } else if (!strcmp(c, "get_tex_image")) {
        img_args[0] = arg_enum();
        img_args[1] = (GLenum)arg_int();
        img_args[2] = arg_enum();
        img_args[3] = arg_enum();
        unsigned char out[QMAX * 8 + 512];
        print_bytes(out, measured(q_teximage, NULL, out, 512, 1));
    } else if (!strcmp(c, "get_polygon_stipple")) {
        unsigned char out[QMAX * 8 + 512];
        print_bytes(out, measured(q_stipple, NULL, out, 512, 1));
    } else {
        return 0;
    }
    return 1;
}
