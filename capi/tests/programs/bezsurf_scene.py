"""The bezsurf scene of bezsurf_scene.h in PyOpenGL, for the pygame and GLUT programs: the Red
Book's bicubic Bezier surface (glMap2f, glMapGrid2f, glEvalMesh2), lit by GL_LIGHT0 with
automatic normals, rotated 85 degrees about (1, 1, 1) in an orthographic view, and in front of
it an unlit yellow glMap1f curve, on a dark blue background; 400x400."""
from OpenGL.GL import *

SIZE = 400

CTRL = [
    [[-1.5, -1.5, 4.0], [-0.5, -1.5, 2.0], [0.5, -1.5, -1.0], [1.5, -1.5, 2.0]],
    [[-1.5, -0.5, 1.0], [-0.5, -0.5, 3.0], [0.5, -0.5, 0.0], [1.5, -0.5, -1.0]],
    [[-1.5, 0.5, 4.0], [-0.5, 0.5, 0.0], [0.5, 0.5, 3.0], [1.5, 0.5, 4.0]],
    [[-1.5, 1.5, -2.0], [-0.5, 1.5, -2.0], [0.5, 1.5, 0.0], [1.5, 1.5, -1.0]],
]
CURVE = [[-3.5, -3.0, 6.0], [-1.5, 3.5, 6.0], [1.5, -3.5, 6.0], [3.5, 3.0, 6.0]]


def transposed(grid):
    """grid[j][i] as [i][j]."""
    return [[grid[j][i] for j in range(len(grid))] for i in range(len(grid[0]))]


def init():
    glClearColor(0.1, 0.1, 0.15, 1.0)
    glEnable(GL_DEPTH_TEST)
    # PyOpenGL's glMap2f(target, u1, u2, v1, v2, points[u][v][3]) takes the strides and
    # orders from the array; C's call glMap2f(..., 0, 1, 3, 4, 0, 1, 12, 4, &ctrl[0][0][0])
    # has u along the inner index, CTRL[v][u], hence the transposition.
    glMap2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 0.0, 1.0, transposed(CTRL))
    glEnable(GL_MAP2_VERTEX_3)
    glEnable(GL_AUTO_NORMAL)
    glMapGrid2f(20, 0.0, 1.0, 20, 0.0, 1.0)
    glMap1f(GL_MAP1_VERTEX_3, 0.0, 1.0, CURVE)
    glEnable(GL_MAP1_VERTEX_3)
    glEnable(GL_LIGHTING)
    glEnable(GL_LIGHT0)
    glLightfv(GL_LIGHT0, GL_AMBIENT, (GLfloat * 4)(0.2, 0.2, 0.2, 1.0))
    glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat * 4)(0.0, 0.0, 2.0, 1.0))
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat * 4)(0.6, 0.6, 0.6, 1.0))
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, (GLfloat * 4)(1.0, 1.0, 1.0, 1.0))
    glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, (GLfloat * 1)(50.0))


def reshape(w, h):
    glViewport(0, 0, w, h)
    glMatrixMode(GL_PROJECTION)
    glLoadIdentity()
    glOrtho(-4.0, 4.0, -4.0 * h / w, 4.0 * h / w, -10.0, 10.0)
    glMatrixMode(GL_MODELVIEW)
    glLoadIdentity()


def display():
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)
    glPushMatrix()
    glRotatef(85.0, 1.0, 1.0, 1.0)
    glEvalMesh2(GL_FILL, 0, 20, 0, 20)
    glPopMatrix()
    glDisable(GL_LIGHTING)
    glColor3f(1.0, 1.0, 0.0)
    glBegin(GL_LINE_STRIP)
    for i in range(31):
        glEvalCoord1f(i / 30.0)
    glEnd()
    glEnable(GL_LIGHTING)


def report():
    print("GL_VENDOR", glGetString(GL_VENDOR).decode())
    print("GL_RENDERER", glGetString(GL_RENDERER).decode(), flush=True)
