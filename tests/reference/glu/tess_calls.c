/* Runs the polygons of tess_cases.in through the installed GLU's tessellator and prints
 * every callback it makes, with exact numbers (IEEE bits in hex), so that gleval's
 * tessellator can be held to the same output (tests/it/glu_tess.rs).
 * Usage: tess_calls < tess_cases.in > tess_calls.txt */
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

typedef struct { int id; double xyz[3]; } Vert;

static Vert *verts[100000];
static int nverts, ncombined;
static int polydata = 77;

static unsigned long long dbits(double d) { unsigned long long u; memcpy(&u, &d, 8); return u; }
static unsigned fbits(float f) { unsigned u; memcpy(&u, &f, 4); return u; }
static int vid(void *p) { return p ? ((Vert *)p)->id : -1; }
static int pid(void *p) { return p ? *(int *)p : -1; }

static Vert *new_vert(int id, const double *c) {
  Vert *v = malloc(sizeof *v);
  v->id = id;
  memcpy(v->xyz, c, sizeof v->xyz);
  verts[nverts++] = v;
  return v;
}

static void GLAPIENTRY on_begin(GLenum t) { printf("begin %u\n", t); }
static void GLAPIENTRY on_vertex(void *d) { printf("vertex %d\n", vid(d)); }
static void GLAPIENTRY on_end(void) { printf("end\n"); }
static void GLAPIENTRY on_error(GLenum e) { printf("error %u\n", e); }
static void GLAPIENTRY on_edge(GLboolean f) { printf("edge %d\n", f); }
static void combine_common(const char *tag, GLdouble c[3], void *d[4], GLfloat w[4], void **out, void *poly) {
  Vert *v = new_vert(1000 + ncombined++, c);
  printf("%s %d %016llx %016llx %016llx | %d %d %d %d | %08x %08x %08x %08x", tag, v->id, dbits(c[0]),
         dbits(c[1]), dbits(c[2]), vid(d[0]), vid(d[1]), vid(d[2]), vid(d[3]), fbits(w[0]), fbits(w[1]),
         fbits(w[2]), fbits(w[3]));
  if (poly) printf(" poly %d", pid(poly));
  printf("\n");
  *out = v;
}
static void GLAPIENTRY on_combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out) {
  combine_common("combine", c, d, w, out, NULL);
}
static void GLAPIENTRY on_begin_data(GLenum t, void *p) { printf("begin %u poly %d\n", t, pid(p)); }
static void GLAPIENTRY on_vertex_data(void *d, void *p) { printf("vertex %d poly %d\n", vid(d), pid(p)); }
static void GLAPIENTRY on_end_data(void *p) { printf("end poly %d\n", pid(p)); }
static void GLAPIENTRY on_error_data(GLenum e, void *p) { printf("error %u poly %d\n", e, pid(p)); }
static void GLAPIENTRY on_edge_data(GLboolean f, void *p) { printf("edge %d poly %d\n", f, pid(p)); }
static void GLAPIENTRY on_combine_data(GLdouble c[3], void *d[4], GLfloat w[4], void **out, void *p) {
  combine_common("combine", c, d, w, out, p);
}

static const struct { const char *name; GLenum which; _GLUfuncptr fn; } callbacks[] = {
  {"begin", GLU_TESS_BEGIN, (_GLUfuncptr)on_begin},
  {"vertex", GLU_TESS_VERTEX, (_GLUfuncptr)on_vertex},
  {"end", GLU_TESS_END, (_GLUfuncptr)on_end},
  {"error", GLU_TESS_ERROR, (_GLUfuncptr)on_error},
  {"edge", GLU_TESS_EDGE_FLAG, (_GLUfuncptr)on_edge},
  {"combine", GLU_TESS_COMBINE, (_GLUfuncptr)on_combine},
  {"begin_data", GLU_TESS_BEGIN_DATA, (_GLUfuncptr)on_begin_data},
  {"vertex_data", GLU_TESS_VERTEX_DATA, (_GLUfuncptr)on_vertex_data},
  {"end_data", GLU_TESS_END_DATA, (_GLUfuncptr)on_end_data},
  {"error_data", GLU_TESS_ERROR_DATA, (_GLUfuncptr)on_error_data},
  {"edge_data", GLU_TESS_EDGE_FLAG_DATA, (_GLUfuncptr)on_edge_data},
  {"combine_data", GLU_TESS_COMBINE_DATA, (_GLUfuncptr)on_combine_data},
};

static GLenum rule_enum(const char *s) {
  if (!strcmp(s, "NONZERO")) return GLU_TESS_WINDING_NONZERO;
  if (!strcmp(s, "POSITIVE")) return GLU_TESS_WINDING_POSITIVE;
  if (!strcmp(s, "NEGATIVE")) return GLU_TESS_WINDING_NEGATIVE;
  if (!strcmp(s, "ABS_GEQ_TWO")) return GLU_TESS_WINDING_ABS_GEQ_TWO;
  return GLU_TESS_WINDING_ODD;
}

static GLUtesselator *tess;
static int next_id;

static void vertex(double x, double y, double z) {
  double c[3] = {x, y, z};
  Vert *v = new_vert(next_id++, c);
  gluTessVertex(tess, v->xyz, v);
}

/* The generator of "random" contours: a 31-bit LCG, coordinates k/8. */
static unsigned lcg_state;
static unsigned lcg(void) { lcg_state = (lcg_state * 1103515245u + 12345u) & 0x7fffffffu; return lcg_state; }

static void end_case(void) {
  if (tess) gluDeleteTess(tess);
  tess = NULL;
}

int main(void) {
  char line[8192];
  while (fgets(line, sizeof line, stdin)) {
    char cmd[64] = "";
    int n = 0;
    if (sscanf(line, "%63s%n", cmd, &n) != 1 || cmd[0] == '#') continue;
    char *rest = line + n;
    if (!strcmp(cmd, "case")) {
      char name[256];
      end_case();
      sscanf(rest, "%255s", name);
      printf("case %s\n", name);
      tess = gluNewTess();
      next_id = 0;
      ncombined = 0;
    } else if (!strcmp(cmd, "cb")) {
      char word[64];
      int k;
      while (sscanf(rest, "%63s%n", word, &k) == 1) {
        rest += k;
        for (size_t i = 0; i < sizeof callbacks / sizeof callbacks[0]; i++)
          if (!strcmp(word, callbacks[i].name)) gluTessCallback(tess, callbacks[i].which, callbacks[i].fn);
      }
    } else if (!strcmp(cmd, "cbraw")) {
      gluTessCallback(tess, (GLenum)strtoul(rest, NULL, 10), NULL);
    } else if (!strcmp(cmd, "rule")) {
      char r[64];
      sscanf(rest, "%63s", r);
      gluTessProperty(tess, GLU_TESS_WINDING_RULE, rule_enum(r));
    } else if (!strcmp(cmd, "prop")) {
      unsigned which;
      double value;
      sscanf(rest, "%u %lf", &which, &value);
      gluTessProperty(tess, which, value);
    } else if (!strcmp(cmd, "get")) {
      unsigned which;
      GLdouble value = -1;
      sscanf(rest, "%u", &which);
      gluGetTessProperty(tess, which, &value);
      printf("value %u %016llx\n", which, dbits(value));
    } else if (!strcmp(cmd, "normal")) {
      double x, y, z;
      sscanf(rest, "%lf %lf %lf", &x, &y, &z);
      gluTessNormal(tess, x, y, z);
    } else if (!strcmp(cmd, "bp")) {
      gluTessBeginPolygon(tess, &polydata);
    } else if (!strcmp(cmd, "bc")) {
      gluTessBeginContour(tess);
    } else if (!strcmp(cmd, "ec")) {
      gluTessEndContour(tess);
    } else if (!strcmp(cmd, "ep")) {
      gluTessEndPolygon(tess);
    } else if (!strcmp(cmd, "v")) {
      double x, y, z;
      sscanf(rest, "%lf %lf %lf", &x, &y, &z);
      vertex(x, y, z);
    } else if (!strcmp(cmd, "c")) {
      double x, y, z;
      int k;
      gluTessBeginContour(tess);
      while (sscanf(rest, "%lf %lf %lf%n", &x, &y, &z, &k) == 3) {
        rest += k;
        vertex(x, y, z);
      }
      gluTessEndContour(tess);
    } else if (!strcmp(cmd, "circle")) {
      int count;
      double cx, cy, r;
      sscanf(rest, "%d %lf %lf %lf", &count, &cx, &cy, &r);
      gluTessBeginContour(tess);
      for (int i = 0; i < count; i++) {
        /* Exact points: the angle's sine and cosine rounded to 1/1024. */
        double a = 6.283185307179586 * i / count;
        double c = (double)(long)(cos(a) * 1024.0) / 1024.0, s = (double)(long)(sin(a) * 1024.0) / 1024.0;
        vertex(cx + r * c, cy + r * s, 0);
      }
      gluTessEndContour(tess);
    } else if (!strcmp(cmd, "random")) {
      int count, size;
      unsigned seed;
      sscanf(rest, "%d %u %d", &count, &seed, &size);
      lcg_state = seed;
      gluTessBeginContour(tess);
      for (int i = 0; i < count; i++) {
        double x = (double)(lcg() % (unsigned)(size * 8)) / 8.0;
        double y = (double)(lcg() % (unsigned)(size * 8)) / 8.0;
        vertex(x, y, 0);
      }
      gluTessEndContour(tess);
    } else if (!strcmp(cmd, "poly")) {
      gluBeginPolygon(tess);
    } else if (!strcmp(cmd, "next")) {
      gluNextContour(tess, GLU_UNKNOWN);
    } else if (!strcmp(cmd, "endpoly")) {
      gluEndPolygon(tess);
    } else {
      fprintf(stderr, "unknown command %s\n", cmd);
      return 1;
    }
  }
  end_case();
  for (int i = 0; i < nverts; i++) free(verts[i]);
  return 0;
}
