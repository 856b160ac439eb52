/* interp.c's commands for vertex arrays, the client attribute stack, edge flags, selection,
 * glPassThrough and the states feedback depends on (lights, polygon mode, culling).
 * Included by interp.c; FORMAT.md §1 describes the commands. */

/* The client's memory the array pointers point into (GL reads it when it draws), and the
 * selection buffer. */
static union { GLubyte b[1 << 16]; double align; } client_mem;
static GLuint select_buf[1024];
static int select_size;      /* values `render_mode` prints after leaving GL_SELECT */

static const GLvoid *mem_at(GLint offset)
{
    if (offset < 0) return NULL;
    if (offset >= (GLint)sizeof client_mem.b) die("client_mem offset out of range", NULL);
    return client_mem.b + offset;
}

/* `buffer_offsets on` (interp_buffers.c): array pointers are offsets into buffer objects. */
static int buffer_offsets;

/* An array or index pointer argument: client_mem+offset, or the offset itself. */
static const GLvoid *ptr_at(GLint offset)
{
    if (buffer_offsets) return offset < 0 ? NULL : (const GLvoid *)(size_t)offset;
    return mem_at(offset);
}

/* `client_mem OFFSET TYPE [values]`: writes the values, cast to TYPE, from byte OFFSET. */
static void set_client_mem(void)
{
    GLint offset = arg_int();
    GLenum type = arg_enum();
    long given;
    double *v = arg_array(1, 0, &given);
    if (!v) die("client_mem needs values", NULL);
    size_t size = type == GL_DOUBLE ? 8 : type == GL_FLOAT || type == GL_INT || type == GL_UNSIGNED_INT ? 4
                : type == GL_SHORT || type == GL_UNSIGNED_SHORT ? 2 : 1;
    if (offset < 0 || (size_t)offset + size * (size_t)given > sizeof client_mem.b) die("client_mem too long", NULL);
    for (long i = 0; i < given; i++) {
        GLubyte *p = client_mem.b + offset + size * (size_t)i;
        double x = v[i];
        switch (type) {
        case GL_BYTE: { GLbyte t = (GLbyte)x; memcpy(p, &t, 1); break; }
        case GL_UNSIGNED_BYTE: { GLubyte t = (GLubyte)x; memcpy(p, &t, 1); break; }
        case GL_SHORT: { GLshort t = (GLshort)x; memcpy(p, &t, 2); break; }
        case GL_UNSIGNED_SHORT: { GLushort t = (GLushort)x; memcpy(p, &t, 2); break; }
        case GL_INT: { GLint t = (GLint)x; memcpy(p, &t, 4); break; }
        case GL_UNSIGNED_INT: { GLuint t = (GLuint)x; memcpy(p, &t, 4); break; }
        case GL_FLOAT: { GLfloat t = (GLfloat)x; memcpy(p, &t, 4); break; }
        case GL_DOUBLE: memcpy(p, &x, 8); break;
        default: die("client_mem type", NULL);
        }
    }
    free(v);
}

static const char *pointer_name(const GLvoid *p)
{
    static char buf[64];
    const GLubyte *b = p;
    if (!p) return "null";
    if (b >= client_mem.b && b < client_mem.b + sizeof client_mem.b)
        snprintf(buf, sizeof buf, "mem+%ld", (long)(b - client_mem.b));
    else if ((const GLuint *)p >= select_buf && (const GLuint *)p < select_buf + 1024)
        snprintf(buf, sizeof buf, "select+%ld", (long)((const GLuint *)p - select_buf));
    else if ((const GLfloat *)p >= fb && (const GLfloat *)p < fb + FB_SIZE)
        snprintf(buf, sizeof buf, "feedback+%ld", (long)((const GLfloat *)p - fb));
    else if ((size_t)p < sizeof client_mem.b)
        snprintf(buf, sizeof buf, "offset+%ld", (long)(size_t)p);
    else
        return "elsewhere";
    return buf;
}

/* Returns 1 when `c` is one of this file's commands (run), 0 otherwise. */
static int run_arrays_call(const char *c)
{
    if (!strcmp(c, "client_mem")) {
        set_client_mem();
    } else if (!strcmp(c, "vertex_pointer") || !strcmp(c, "color_pointer") || !strcmp(c, "tex_coord_pointer")
               || !strcmp(c, "secondary_color_pointer")) {
        GLint size = arg_int();
        GLenum type = arg_enum();
        GLsizei stride = arg_int();
        const GLvoid *p = ptr_at(arg_int());
        if (c[0] == 'v') glVertexPointer(size, type, stride, p);
        else if (c[0] == 'c') glColorPointer(size, type, stride, p);
        else if (c[0] == 's') glSecondaryColorPointer(size, type, stride, p);
        else glTexCoordPointer(size, type, stride, p);
    } else if (!strcmp(c, "normal_pointer") || !strcmp(c, "index_pointer") || !strcmp(c, "fog_coord_pointer")) {
        GLenum type = arg_enum();
        GLsizei stride = arg_int();
        const GLvoid *p = ptr_at(arg_int());
        if (c[0] == 'n') glNormalPointer(type, stride, p);
        else if (c[0] == 'f') glFogCoordPointer(type, stride, p);
        else glIndexPointer(type, stride, p);
    } else if (!strcmp(c, "edge_flag_pointer")) {
        GLsizei stride = arg_int();
        glEdgeFlagPointer(stride, ptr_at(arg_int()));
    } else if (!strcmp(c, "interleaved_arrays")) {
        GLenum format = arg_enum();
        GLsizei stride = arg_int();
        glInterleavedArrays(format, stride, ptr_at(arg_int()));
    } else if (!strcmp(c, "enable_client_state")) {
        glEnableClientState(arg_enum());
    } else if (!strcmp(c, "disable_client_state")) {
        glDisableClientState(arg_enum());
    } else if (!strcmp(c, "array_element")) {
        glArrayElement(arg_int());
    } else if (!strcmp(c, "draw_arrays")) {
        GLenum mode = arg_enum();
        GLint first = arg_int();
        glDrawArrays(mode, first, arg_int());
    } else if (!strcmp(c, "draw_elements")) {
        GLenum mode = arg_enum();
        GLsizei count = arg_int();
        GLenum type = arg_enum();
        glDrawElements(mode, count, type, ptr_at(arg_int()));
    } else if (!strcmp(c, "draw_range_elements")) {
        GLenum mode = arg_enum();
        GLuint start = (GLuint)arg_int();
        GLuint end = (GLuint)arg_int();
        GLsizei count = arg_int();
        GLenum type = arg_enum();
        glDrawRangeElements(mode, start, end, count, type, ptr_at(arg_int()));
    } else if (!strcmp(c, "multi_draw_arrays")) {
        /* multi_draw_arrays MODE FIRSTS COUNTS PRIMCOUNT: the firsts and counts are GLint
         * arrays in client memory at those offsets. */
        GLenum mode = arg_enum();
        const GLint *first = mem_at(arg_int());
        const GLsizei *count = mem_at(arg_int());
        glMultiDrawArrays(mode, first, count, arg_int());
    } else if (!strcmp(c, "multi_draw_elements")) {
        /* multi_draw_elements MODE COUNTS TYPE PRIMCOUNT OFFSET...: one index array offset
         * each (up to 8). */
        GLenum mode = arg_enum();
        const GLsizei *count = mem_at(arg_int());
        GLenum type = arg_enum();
        GLsizei n = arg_int();
        const GLvoid *indices[8] = {0};
        for (GLsizei i = 0; i < n && i < 8; i++) indices[i] = ptr_at(arg_int());
        glMultiDrawElements(mode, count, type, indices, n);
    } else if (!strcmp(c, "get_pointerv")) {
        GLvoid *p = (GLvoid *)&p;   /* not NULL: shows whether GL wrote it */
        glGetPointerv(arg_enum(), &p);
        val(" %s", p == (GLvoid *)&p ? "unwritten" : pointer_name(p));
    } else if (!strcmp(c, "push_client_attrib")) {
        glPushClientAttrib(arg_enum());
    } else if (!strcmp(c, "pop_client_attrib")) {
        glPopClientAttrib();
    } else if (!strcmp(c, "edge_flag")) {
        glEdgeFlag((GLboolean)arg_int());
    } else if (!strcmp(c, "select_buffer") || !strcmp(c, "select_buffer_null")) {
        GLsizei size = arg_int();
        for (int i = 0; i < 1024; i++) select_buf[i] = 7777;
        glSelectBuffer(size, c[13] ? NULL : select_buf);
        select_size = size < 0 ? 0 : size > 64 ? 64 : size;
    } else if (!strcmp(c, "render_mode")) {
        GLint before = 0;
        glGetIntegerv(GL_RENDER_MODE, &before);
        GLint n = glRenderMode(arg_enum());
        val(" %d", n);
        if (before == GL_SELECT)
            for (int i = 0; i < select_size; i++) val(" %u", select_buf[i]);
    } else if (!strcmp(c, "init_names")) {
        glInitNames();
    } else if (!strcmp(c, "load_name")) {
        glLoadName((GLuint)arg_int());
    } else if (!strcmp(c, "push_name")) {
        glPushName((GLuint)arg_int());
    } else if (!strcmp(c, "pop_name")) {
        glPopName();
    } else if (!strcmp(c, "pass_through")) {
        glPassThrough(arg_float());
    } else if (!strcmp(c, "gl_feedback")) {
        /* The Rust runner reads gleval's own feedback mode from here on (FORMAT.md). */
    } else if (!strcmp(c, "lightfv") || !strcmp(c, "materialfv")) {
        GLenum a = arg_enum(), pname = arg_enum();
        long given;
        float *v = arg_array(0, 4, &given);
        if (c[0] == 'l') glLightfv(a, pname, v);
        else glMaterialfv(a, pname, v);
        free(v);
    } else if (!strcmp(c, "polygon_mode")) {
        GLenum face = arg_enum();
        glPolygonMode(face, arg_enum());
    } else if (!strcmp(c, "cull_face")) {
        glCullFace(arg_enum());
    } else if (!strcmp(c, "front_face")) {
        glFrontFace(arg_enum());
    } else if (!strcmp(c, "shade_model")) {
        glShadeModel(arg_enum());
    } else if (!strcmp(c, "ortho")) {
        double l = arg_double(), r = arg_double(), b = arg_double(), t = arg_double(), n = arg_double();
        glOrtho(l, r, b, t, n, arg_double());
    } else if (!strcmp(c, "viewport")) {
        GLint x = arg_int(), y = arg_int(), w = arg_int();
        glViewport(x, y, w, arg_int());
    } else if (!strcmp(c, "depth_range")) {
        double n = arg_double();
        glDepthRange(n, arg_double());
    } else if (!strcmp(c, "matrix_mode")) {
        glMatrixMode(arg_enum());
    } else {
        return 0;
    }
    return 1;
}
