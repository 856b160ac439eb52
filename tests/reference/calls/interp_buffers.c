/* interp.c's commands for GL 1.5's buffer objects (ARB_vertex_buffer_object; Mesa
 * main/bufferobj.c). Included by interp.c after interp_arrays.c; FORMAT.md §1 describes them.
 *   buffer_offsets on|off          the array and index pointer arguments are offsets into the
 *                                  bound buffers (the integer as a pointer) instead of client_mem
 *   gen_buffers N                  glGenBuffers; prints the names (N up to 16)
 *   delete_buffers N [names]       glDeleteBuffers
 *   is_buffer NAME                 glIsBuffer; prints the result
 *   bind_buffer TARGET NAME        glBindBuffer
 *   buffer_data TARGET SIZE MEM USAGE
 *                                  glBufferData from client_mem+MEM (MEM -1: NULL)
 *   buffer_sub_data TARGET OFFSET SIZE MEM
 *                                  glBufferSubData from client_mem+MEM
 *   get_buffer_sub_data TARGET OFFSET SIZE
 *                                  glGetBufferSubData; prints the first bytes (at most 32) it
 *                                  wrote, as bytes of a buffer filled with 238 first
 *   map_buffer TARGET ACCESS       glMapBuffer; prints null or mapped
 *   map_write OFFSET TYPE [values] writes into the last mapped pointer as client_mem does
 *   map_read OFFSET N              prints N bytes of the last mapped pointer
 *   unmap_buffer TARGET            glUnmapBuffer; prints the result
 *   get_buffer_parameteriv TARGET PNAME
 *                                  prints the value, or unwritten
 *   get_buffer_pointerv TARGET PNAME
 *                                  prints unwritten, null, map (the last mapped pointer) or
 *                                  elsewhere */

static GLubyte *mapped;

/* `type` of `client_mem`'s values as bytes at p. */
static void write_typed(GLubyte *p, GLenum type, const double *v, long given)
{
    size_t size = type == GL_FLOAT || type == GL_INT || type == GL_UNSIGNED_INT ? 4
                : type == GL_SHORT || type == GL_UNSIGNED_SHORT ? 2 : 1;
    for (long i = 0; i < given; i++, p += size) {
        switch (type) {
        case GL_UNSIGNED_BYTE: { GLubyte t = (GLubyte)v[i]; memcpy(p, &t, 1); break; }
        case GL_UNSIGNED_SHORT: { GLushort t = (GLushort)v[i]; memcpy(p, &t, 2); break; }
        case GL_UNSIGNED_INT: { GLuint t = (GLuint)v[i]; memcpy(p, &t, 4); break; }
        case GL_FLOAT: { GLfloat t = (GLfloat)v[i]; memcpy(p, &t, 4); break; }
        default: die("map_write type", NULL);
        }
    }
}

/* Returns 1 when `c` is one of this file's commands (run), 0 otherwise. */
static int run_buffers_call(const char *c)
{
    if (!strcmp(c, "buffer_offsets")) {
        const char *v = next();
        if (strcmp(v, "on") && strcmp(v, "off")) die("buffer_offsets on|off", v);
        buffer_offsets = v[1] == 'n';
    } else if (!strcmp(c, "gen_buffers")) {
        GLsizei n = arg_int();
        GLuint names[16];
        for (int i = 0; i < 16; i++) names[i] = 7777;
        if (n > 16) die("gen_buffers: at most 16", NULL);
        glGenBuffers(n, names);
        for (GLsizei i = 0; i < n; i++) val(" %u", names[i]);
    } else if (!strcmp(c, "delete_buffers")) {
        GLsizei n = arg_int();
        long given;
        double *v = arg_array(1, 0, &given);
        GLuint names[16] = {0};
        for (long i = 0; v && i < given && i < 16; i++) names[i] = (GLuint)v[i];
        glDeleteBuffers(n, v ? names : NULL);
        free(v);
    } else if (!strcmp(c, "is_buffer")) {
        val(" %d", glIsBuffer((GLuint)arg_int()));
    } else if (!strcmp(c, "bind_buffer")) {
        GLenum target = arg_enum();
        glBindBuffer(target, (GLuint)arg_int());
    } else if (!strcmp(c, "buffer_data")) {
        GLenum target = arg_enum();
        GLsizeiptr size = arg_int();
        GLint mem = arg_int();
        glBufferData(target, size, mem < 0 ? NULL : client_mem.b + mem, arg_enum());
    } else if (!strcmp(c, "buffer_sub_data")) {
        GLenum target = arg_enum();
        GLintptr offset = arg_int();
        GLsizeiptr size = arg_int();
        glBufferSubData(target, offset, size, client_mem.b + arg_int());
    } else if (!strcmp(c, "get_buffer_sub_data")) {
        GLenum target = arg_enum();
        GLintptr offset = arg_int();
        GLsizeiptr size = arg_int();
        static GLubyte out[1 << 16];
        memset(out, 238, sizeof out);
        glGetBufferSubData(target, offset, size, out);
        for (GLsizeiptr i = 0; i < size && i < 32; i++) val(" %u", out[i]);
    } else if (!strcmp(c, "map_buffer")) {
        GLenum target = arg_enum();
        GLvoid *p = glMapBuffer(target, arg_enum());
        if (p) mapped = p;
        val(" %s", p ? "mapped" : "null");
    } else if (!strcmp(c, "map_write")) {
        GLint offset = arg_int();
        GLenum type = arg_enum();
        long given;
        double *v = arg_array(1, 0, &given);
        if (!mapped || !v) die("map_write needs a mapping and values", NULL);
        write_typed(mapped + offset, type, v, given);
        free(v);
    } else if (!strcmp(c, "map_read")) {
        GLint offset = arg_int();
        GLint n = arg_int();
        if (!mapped) die("map_read needs a mapping", NULL);
        for (GLint i = 0; i < n; i++) val(" %u", mapped[offset + i]);
    } else if (!strcmp(c, "unmap_buffer")) {
        val(" %d", glUnmapBuffer(arg_enum()));
    } else if (!strcmp(c, "get_buffer_parameteriv")) {
        GLenum target = arg_enum();
        GLint v = 7777;
        glGetBufferParameteriv(target, arg_enum(), &v);
        if (v == 7777) val(" unwritten");
        else val(" %d", v);
    } else if (!strcmp(c, "get_buffer_pointerv")) {
        GLenum target = arg_enum();
        GLvoid *p = (GLvoid *)&p;
        glGetBufferPointerv(target, arg_enum(), &p);
        val(" %s", p == (GLvoid *)&p ? "unwritten" : !p ? "null" : p == (GLvoid *)mapped ? "map" : "elsewhere");
    } else {
        return 0;
    }
    return 1;
}

/* GL 1.5's occlusion queries (ARB_occlusion_query; Mesa main/queryobj.c):
 *   gen_queries N, delete_queries N [names], is_query NAME, begin_query TARGET NAME,
 *   end_query TARGET        as the buffer commands above
 *   get_queryiv TARGET PNAME, get_query_objectiv NAME PNAME, get_query_objectuiv NAME PNAME
 *                           print the value, or unwritten */
static int run_queries_objects_call(const char *c)
{
    if (!strcmp(c, "gen_queries")) {
        GLsizei n = arg_int();
        GLuint names[16];
        for (int i = 0; i < 16; i++) names[i] = 7777;
        if (n > 16) die("gen_queries: at most 16", NULL);
        glGenQueries(n, names);
        for (GLsizei i = 0; i < n; i++) val(" %u", names[i]);
    } else if (!strcmp(c, "delete_queries")) {
        GLsizei n = arg_int();
        long given;
        double *v = arg_array(1, 0, &given);
        GLuint names[16] = {0};
        for (long i = 0; v && i < given && i < 16; i++) names[i] = (GLuint)v[i];
        glDeleteQueries(n, v ? names : NULL);
        free(v);
    } else if (!strcmp(c, "is_query")) {
        val(" %d", glIsQuery((GLuint)arg_int()));
    } else if (!strcmp(c, "begin_query")) {
        GLenum target = arg_enum();
        glBeginQuery(target, (GLuint)arg_int());
    } else if (!strcmp(c, "end_query")) {
        glEndQuery(arg_enum());
    } else if (!strcmp(c, "get_queryiv") || !strcmp(c, "get_query_objectiv") || !strcmp(c, "get_query_objectuiv")) {
        GLenum a = c[9] == 'i' ? arg_enum() : (GLenum)arg_int();
        GLenum pname = arg_enum();
        GLint v = 7777;
        if (c[9] == 'i') glGetQueryiv(a, pname, &v);
        else if (c[16] == 'i') glGetQueryObjectiv(a, pname, &v);
        else glGetQueryObjectuiv(a, pname, (GLuint *)&v);
        if (v == 7777) val(" unwritten");
        else val(" %d", v);
    } else {
        return 0;
    }
    return 1;
}
