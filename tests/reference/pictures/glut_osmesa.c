/* GLUT stand-in over OSMesa; see glut_osmesa.h. Writes the PNG with zlib (no libpng). */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <zlib.h>
#include "glut_osmesa.h"
#include "glut_fonts.h"
#include "glut_strokes.h"
#include "glut_teapot.h"
#include "glut_shapes.h"

static int width = 300, height = 300, frames = 0;
static const char *png_path = "out.png";
static void (*display)(void);
static void (*reshape)(int, int);
static unsigned char *pixels;

void glutInit(int *argc, char **argv) {
    for (int i = 1; i < *argc; i++) {
        if (!strcmp(argv[i], "--png") && i + 1 < *argc) png_path = argv[++i];
        else if (!strcmp(argv[i], "--time") && i + 1 < *argc) frames = atoi(argv[++i]);
    }
}
void glutInitWindowSize(int w, int h) { width = w; height = h; }
void glutInitWindowPosition(int x, int y) { (void)x; (void)y; }
static unsigned int display_mode;
/* Kept for glutCreateWindow: GLUT_STENCIL and GLUT_ACCUM ask for the buffers freeglut gives. */
void glutInitDisplayMode(unsigned int mode) { display_mode = mode; }
void glutDisplayFunc(void (*f)(void)) { display = f; }
void glutReshapeFunc(void (*f)(int, int)) { reshape = f; }
void glutKeyboardFunc(void (*f)(unsigned char, int, int)) { (void)f; }
void glutMouseFunc(void (*f)(int, int, int, int)) { (void)f; }
void glutMotionFunc(void (*f)(int, int)) { (void)f; }
static int menus;
int glutCreateMenu(void (*f)(int)) { (void)f; return ++menus; }
void glutAddMenuEntry(const char *label, int value) { (void)label; (void)value; }
void glutAttachMenu(int button) { (void)button; }
void glutPostRedisplay(void) {}
void glutSwapBuffers(void) { glFinish(); }
int glutGet(unsigned int what) {
    return what == GLUT_WINDOW_WIDTH ? width : what == GLUT_WINDOW_HEIGHT ? height : -1;
}

/* The glyph of `c` in `font` and its rows, or NULL (codes outside 1..255 and ones the font lacks). */
static const GlutGlyph *glyph(void *font, int c, const unsigned char **bits) {
    static const struct { const GlutGlyph *glyphs; const unsigned char *bits; } fonts[] = {
        {FIXED_9_BY_15_GLYPHS, FIXED_9_BY_15_BITS},   {FIXED_8_BY_13_GLYPHS, FIXED_8_BY_13_BITS},
        {TIMES_ROMAN_10_GLYPHS, TIMES_ROMAN_10_BITS}, {TIMES_ROMAN_24_GLYPHS, TIMES_ROMAN_24_BITS},
        {HELVETICA_10_GLYPHS, HELVETICA_10_BITS},     {HELVETICA_12_GLYPHS, HELVETICA_12_BITS},
        {HELVETICA_18_GLYPHS, HELVETICA_18_BITS},
    };
    size_t id = (size_t)font;
    if (id < 2 || id > 8 || c < 1 || c > 255) return NULL;
    const GlutGlyph *g = &fonts[id - 2].glyphs[c];
    if (g->offset < 0) return NULL;
    *bits = fonts[id - 2].bits + g->offset;
    return g;
}

/* As freeglut: glBitmap with the glyph's metrics, unpack alignment 1, the client's modes kept. */
void glutBitmapCharacter(void *font, int character) {
    const unsigned char *bits;
    const GlutGlyph *g = glyph(font, character, &bits);
    if (!g) return;
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBitmap(g->width, g->height, g->xorig, g->yorig, g->advance, 0, bits);
    glPopClientAttrib();
}

/* As freeglut's glutBitmapString: the characters one after another, the client's modes kept; a
   newline moves the raster position back to where the line started and down by the font's
   height (its glyphs' largest ascent plus largest descent plus 1, as freeglut's fonts record). */
void glutBitmapString(void *font, const unsigned char *string) {
    const unsigned char *bits;
    int ascent = 0, descent = 0;
    for (int c = 1; c < 256; c++) {
        const GlutGlyph *g = glyph(font, c, &bits);
        if (!g) continue;
        if (g->height - g->yorig > ascent) ascent = g->height - g->yorig;
        if (g->yorig > descent) descent = g->yorig;
    }
    float x = 0.0f;
    for (; string && *string; string++) {
        if (*string == '\n') {
            glBitmap(0, 0, 0, 0, -x, (float)-(ascent + descent + 1), NULL);
            x = 0.0f;
        } else if (glyph(font, *string, &bits)) {
            glutBitmapCharacter(font, *string);
            x += glutBitmapWidth(font, *string);
        }
    }
}
int glutBitmapWidth(void *font, int character) {
    const unsigned char *bits;
    const GlutGlyph *g = glyph(font, character, &bits);
    return g ? g->advance : 0;
}

int glutBitmapLength(void *font, const unsigned char *string) {
    int longest = 0, line = 0;
    for (; *string; string++) {
        if (*string == '\n') line = 0;
        else line += glutBitmapWidth(font, *string);
        if (line > longest) longest = line;
    }
    return longest;
}

/* Stroke fonts, as freeglut draws them: a GL_LINE_STRIP of glVertex2f a pen stroke, then
   glTranslatef by the advance; glyphs from glut_strokes.h (tools/fonts/gen_stroke.py). */
static const GlutStrokeGlyph *stroke_glyph(void *font, int c, const GlutStrokeFont **f) {
    *f = (size_t)font == 0 ? &ROMAN : &MONO_ROMAN;
    return c >= 0 && c < 128 && (*f)->glyphs[c].present ? &(*f)->glyphs[c] : NULL;
}

void glutStrokeCharacter(void *font, int character) {
    const GlutStrokeFont *f;
    const GlutStrokeGlyph *g = stroke_glyph(font, character, &f);
    if (!g) return;
    for (int s = g->first; s < g->first + g->count; s++) {
        glBegin(GL_LINE_STRIP);
        for (int k = f->strips[s][0]; k < f->strips[s][0] + f->strips[s][1]; k++)
            glVertex2f(f->points[k][0], f->points[k][1]);
        glEnd();
    }
    glTranslatef(g->advance, 0.0f, 0.0f);
}

/* freeglut's glutStrokeString: a newline goes back to the line's start and down by the height. */
void glutStrokeString(void *font, const unsigned char *string) {
    const GlutStrokeFont *f;
    float line = 0.0f;
    stroke_glyph(font, 0, &f);
    for (; string && *string; string++) {
        if (*string == '\n') {
            glTranslatef(-line, -f->height, 0.0f);
            line = 0.0f;
        } else if (stroke_glyph(font, *string, &f)) {
            glutStrokeCharacter(font, *string);
            line += f->glyphs[*string].advance;
        }
    }
}

float glutStrokeWidthf(void *font, int character) {
    const GlutStrokeFont *f;
    const GlutStrokeGlyph *g = stroke_glyph(font, character, &f);
    return g ? g->advance : 0.0f;
}

int glutStrokeWidth(void *font, int character) { return (int)(glutStrokeWidthf(font, character) + 0.5f); }

float glutStrokeLengthf(void *font, const unsigned char *string) {
    float longest = 0.0f, line = 0.0f;
    for (; *string; string++) {
        if (*string == '\n') line = 0.0f;
        else line += glutStrokeWidthf(font, *string);
        if (line > longest) longest = line;
    }
    return longest;
}

int glutStrokeLength(void *font, const unsigned char *string) { return (int)(glutStrokeLengthf(font, string) + 0.5f); }

float glutStrokeHeight(void *font) {
    const GlutStrokeFont *f;
    stroke_glyph(font, 0, &f);
    return f->height;
}

int glutCreateWindow(const char *title) {
    (void)title;
    /* As freeglut on Mesa: 8 stencil bits with GLUT_STENCIL, 16 accumulation bits with GLUT_ACCUM. */
    int stencil = display_mode & GLUT_STENCIL ? 8 : 0, accum = display_mode & GLUT_ACCUM ? 16 : 0;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, stencil, accum, NULL);
    pixels = calloc((size_t)width * height, 4);
    if (!ctx || !pixels || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, width, height)) {
        fprintf(stderr, "OSMesa context failed\n");
        exit(1);
    }
    return 1;
}

static uint32_t crc_table[256];
/* PNG's CRC-32 over the chunk type and data. */
static uint32_t crc(uint32_t c, const unsigned char *p, size_t n) {
    if (!crc_table[1])
        for (uint32_t i = 0; i < 256; i++) {
            uint32_t v = i;
            for (int k = 0; k < 8; k++) v = (v & 1) ? 0xEDB88320u ^ (v >> 1) : v >> 1;
            crc_table[i] = v;
        }
    c ^= 0xFFFFFFFFu;
    while (n--) c = crc_table[(c ^ *p++) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}
static void be32(unsigned char *p, uint32_t v) { p[0] = v >> 24; p[1] = v >> 16; p[2] = v >> 8; p[3] = v; }
static void chunk(FILE *f, const char *type, const unsigned char *data, uint32_t n) {
    unsigned char h[8];
    be32(h, n);
    memcpy(h + 4, type, 4);
    fwrite(h, 1, 8, f);
    fwrite(data, 1, n, f);
    uint32_t c = crc(crc(0, (const unsigned char *)type, 4), data, n);
    be32(h, c);
    fwrite(h, 1, 4, f);
}

/* RGB PNG, rows top first (GL's rows are bottom first). */
static void write_png(const char *path) {
    size_t row = (size_t)width * 3 + 1, raw_n = row * height;
    unsigned char *raw = malloc(raw_n);
    /* Read through GL: OSMesa does not copy what glAccum(GL_RETURN) wrote into the caller's
     * buffer at the next glFinish (measured on Mesa 22.3), glReadPixels sees it. */
    unsigned char *read = malloc((size_t)width * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, read);
    for (int y = 0; y < height; y++) {
        unsigned char *dst = raw + row * y, *src = read + (size_t)(height - 1 - y) * width * 4;
        dst[0] = 0;
        for (int x = 0; x < width; x++) memcpy(dst + 1 + 3 * x, src + 4 * x, 3);
    }
    uLongf z_n = compressBound(raw_n);
    unsigned char *z = malloc(z_n);
    if (compress2(z, &z_n, raw, raw_n, 9) != Z_OK) { fprintf(stderr, "zlib failed\n"); exit(1); }
    FILE *f = fopen(path, "wb");
    if (!f) { perror(path); exit(1); }
    fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
    unsigned char ihdr[13];
    be32(ihdr, width); be32(ihdr + 4, height);
    ihdr[8] = 8; ihdr[9] = 2; ihdr[10] = ihdr[11] = ihdr[12] = 0;
    chunk(f, "IHDR", ihdr, 13);
    chunk(f, "IDAT", z, (uint32_t)z_n);
    chunk(f, "IEND", NULL, 0);
    fclose(f);
    free(raw);
    free(z);
}

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}
static int by_value(const void *x, const void *y) {
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

static void frame(void) {
    if (reshape) reshape(width, height); else glViewport(0, 0, width, height);
    if (display) display();
    glFinish();
}

void glutMainLoop(void) {
    frame();
    if (frames > 0) {
        double *t = malloc(sizeof *t * frames);
        for (int i = 0; i < frames; i++) { double s = now(); frame(); t[i] = now() - s; }
        qsort(t, frames, sizeof *t, by_value);
        printf("OSMesa: median frame %.3f ms over %d frames\n", t[frames / 2] * 1e3, frames);
        exit(0);
    }
    write_png(png_path);
    exit(0);
}
