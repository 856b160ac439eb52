/* The pixel path's calls for interp.c (included by it): transfer, maps, zoom, copies, the
 * texture calls that read the window, residency and priorities, colour index, reads.
 * Returns 1 when `c` was one of them. Enums are given as numbers in the cases
 * (cases/pixels.calls names them in comments). */

static void print_pixel_map(const char *c, GLenum map)
{
    GLint size = 0;
    if (map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A)
        glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE + (map - GL_PIXEL_MAP_I_TO_I), &size);
    /* Mesa's error state after glGetIntegerv is clean; the call below sets its own. */
    static GLfloat f[256];
    static GLuint u[256];
    static GLushort s[256];
    char t = c[13], t2 = c[14]; /* get_pixel_map[f|ui|us]v */
    if (t == 'f') glGetPixelMapfv(map, f);
    else if (t2 == 'i') glGetPixelMapuiv(map, u);
    else glGetPixelMapusv(map, s);
    for (GLint i = 0; i < size; i++) {
        if (t == 'f') val(" %.9g", f[i]);
        else if (t2 == 'i') val(" %u", u[i]);
        else val(" %u", s[i]);
    }
}

static int run_pixel_call(const char *c)
{
    long given = 0;
    if (!strcmp(c, "pixel_zoom")) {
        GLfloat x = arg_float();
        glPixelZoom(x, arg_float());
    } else if (!strcmp(c, "pixel_transferf")) {
        GLenum p = arg_enum();
        glPixelTransferf(p, arg_float());
    } else if (!strcmp(c, "pixel_transferi")) {
        GLenum p = arg_enum();
        glPixelTransferi(p, arg_int());
    } else if (!strcmp(c, "pixel_mapfv") || !strcmp(c, "pixel_mapuiv") || !strcmp(c, "pixel_mapusv")) {
        GLenum map = arg_enum();
        GLsizei n = arg_int();
        double *d = arg_array(1, 0, &given);
        if (d && given < n && n <= 256) die("pixel map shorter than mapsize", NULL);
        static GLfloat f[256];
        static GLuint u[256];
        static GLushort s[256];
        for (long i = 0; d && i < given && i < 256; i++) {
            f[i] = (GLfloat)d[i];
            u[i] = (GLuint)d[i];
            s[i] = (GLushort)d[i];
        }
        char t = c[9], t2 = c[10]; /* pixel_map[f|ui|us]v */
        if (t == 'f') glPixelMapfv(map, n, d ? f : NULL);
        else if (t2 == 'i') glPixelMapuiv(map, n, d ? u : NULL);
        else glPixelMapusv(map, n, d ? s : NULL);
        free(d);
    } else if (!strcmp(c, "get_pixel_mapfv") || !strcmp(c, "get_pixel_mapuiv") || !strcmp(c, "get_pixel_mapusv")) {
        print_pixel_map(c, arg_enum());
    } else if (!strcmp(c, "copy_pixels")) {
        GLint x = arg_int(), y = arg_int();
        GLsizei w = arg_int(), h = arg_int();
        glCopyPixels(x, y, w, h, arg_enum());
    } else if (!strcmp(c, "copy_tex_image_2d")) {
        GLenum t = arg_enum(); GLint level = arg_int(); GLenum f = arg_enum();
        GLint x = arg_int(), y = arg_int(); GLsizei w = arg_int(), h = arg_int();
        glCopyTexImage2D(t, level, f, x, y, w, h, arg_int());
    } else if (!strcmp(c, "copy_tex_image_1d")) {
        GLenum t = arg_enum(); GLint level = arg_int(); GLenum f = arg_enum();
        GLint x = arg_int(), y = arg_int(); GLsizei w = arg_int();
        glCopyTexImage1D(t, level, f, x, y, w, arg_int());
    } else if (!strcmp(c, "copy_tex_sub_image_2d")) {
        GLenum t = arg_enum(); GLint level = arg_int(); GLint xo = arg_int(), yo = arg_int();
        GLint x = arg_int(), y = arg_int(); GLsizei w = arg_int();
        glCopyTexSubImage2D(t, level, xo, yo, x, y, w, arg_int());
    } else if (!strcmp(c, "copy_tex_sub_image_3d")) {
        GLenum t = arg_enum(); GLint level = arg_int();
        GLint xo = arg_int(), yo = arg_int(), zo = arg_int();
        GLint x = arg_int(), y = arg_int(); GLsizei w = arg_int();
        glCopyTexSubImage3D(t, level, xo, yo, zo, x, y, w, arg_int());
    } else if (!strcmp(c, "copy_tex_sub_image_1d")) {
        GLenum t = arg_enum(); GLint level = arg_int(); GLint xo = arg_int();
        GLint x = arg_int(), y = arg_int();
        glCopyTexSubImage1D(t, level, xo, x, y, arg_int());
    } else if (!strcmp(c, "tex_sub_image_1d")) {
        GLenum t = arg_enum(); GLint level = arg_int(); GLint xo = arg_int(); GLsizei w = arg_int();
        GLenum format = arg_enum(), type = arg_enum();
        float *f = arg_array(0, 0, &given);
        GLubyte bytes[MAX_TOK];
        for (long i = 0; i < given && i < MAX_TOK; i++) bytes[i] = (GLubyte)f[i];
        glTexSubImage1D(t, level, xo, w, format, type, f ? (const GLvoid *)bytes : NULL);
        free(f);
    } else if (!strcmp(c, "are_textures_resident")) {
        GLsizei n = arg_int();
        float *f = arg_array(0, 0, &given);
        GLuint names[MAX_TOK];
        GLboolean res[MAX_TOK];
        for (long i = 0; i < MAX_TOK; i++) { names[i] = i < given ? (GLuint)f[i] : 0; res[i] = 7; }
        GLboolean r = glAreTexturesResident(n, f ? names : NULL, res);
        val(" %d", (int)r);
        for (long i = 0; i < given; i++) val(" %d", (int)res[i]);
        free(f);
    } else if (!strcmp(c, "prioritize_textures")) {
        GLsizei n = arg_int();
        long given2 = 0;
        float *names_f = arg_array(0, 0, &given);
        float *prios = arg_array(0, 0, &given2);
        GLuint names[MAX_TOK];
        for (long i = 0; i < given && i < MAX_TOK; i++) names[i] = (GLuint)names_f[i];
        glPrioritizeTextures(n, names_f ? names : NULL, prios);
        free(names_f);
        free(prios);
    } else if (!strcmp(c, "indexf")) {
        glIndexf(arg_float());
    } else if (!strcmp(c, "indexd")) {
        glIndexd(arg_double());
    } else if (!strcmp(c, "indexi")) {
        glIndexi(arg_int());
    } else if (!strcmp(c, "indexs")) {
        glIndexs((GLshort)arg_int());
    } else if (!strcmp(c, "indexub")) {
        glIndexub((GLubyte)arg_int());
    } else if (!strcmp(c, "clear_index")) {
        glClearIndex(arg_float());
    } else if (!strcmp(c, "index_mask")) {
        glIndexMask((GLuint)strtoul(next(), NULL, 0));
    } else if (!strcmp(c, "read_pixels")) {
        /* read_pixels x y w h format type: prints what was written (floats for GL_FLOAT,
         * else bytes); the buffer starts as 0xEE bytes so that untouched bytes show. */
        GLint x = arg_int(), y = arg_int();
        GLsizei w = arg_int(), h = arg_int();
        GLenum format = arg_enum(), type = arg_enum();
        static unsigned char out[4096];
        memset(out, 0xEE, sizeof out);
        glReadPixels(x, y, w, h, format, type, out);
        long n = w > 0 && h > 0 ? (long)w * h : 0;
        if (type != GL_FLOAT) n = 16;
        if (n > 16) n = 16;
        for (long i = 0; i < n; i++) {
            if (type == GL_FLOAT) { GLfloat v; memcpy(&v, out + 4 * i, 4); val(" %.6g", v); }
            else val(" %d", out[i]);
        }
    } else if (!strcmp(c, "pixels_clear")) {
        /* pixels_clear r g b a depth: clears colour and depth (the buffer starts undefined),
         * in render mode (Mesa clears nothing in feedback mode), then feedback resumes. */
        GLfloat r = arg_float(), g = arg_float(), b = arg_float(), a = arg_float();
        glClearColor(r, g, b, a);
        glClearDepth(arg_double());
        glRenderMode(GL_RENDER);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        start_feedback();
    } else {
        return 0;
    }
    return 1;
}
