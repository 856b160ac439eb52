"""pyglet 1.5 (pyglet.gl only): the bezsurf scene (bezsurf_scene.h) in a 400x400 double-buffered
window with a 16-bit depth buffer titled "bezsurf pyglet", redrawn every 100 ms; exits after 3 s.
   python3 pyglet_bezsurf.py"""
import pyglet
from pyglet.gl import *

SIZE = 400
CTRL = [
    -1.5, -1.5, 4.0, -0.5, -1.5, 2.0, 0.5, -1.5, -1.0, 1.5, -1.5, 2.0,
    -1.5, -0.5, 1.0, -0.5, -0.5, 3.0, 0.5, -0.5, 0.0, 1.5, -0.5, -1.0,
    -1.5, 0.5, 4.0, -0.5, 0.5, 0.0, 0.5, 0.5, 3.0, 1.5, 0.5, 4.0,
    -1.5, 1.5, -2.0, -0.5, 1.5, -2.0, 0.5, 1.5, 0.0, 1.5, 1.5, -1.0,
]
CURVE = [-3.5, -3.0, 6.0, -1.5, 3.5, 6.0, 1.5, -3.5, 6.0, 3.5, 3.0, 6.0]


def floats(*values):
    return (GLfloat * len(values))(*values)


config = pyglet.gl.Config(double_buffer=True, depth_size=16)
window = pyglet.window.Window(SIZE, SIZE, caption="bezsurf pyglet", config=config)
window.set_location(0, 0)

from ctypes import cast, c_char_p

print("GL_VENDOR", cast(glGetString(GL_VENDOR), c_char_p).value.decode())
print("GL_RENDERER", cast(glGetString(GL_RENDERER), c_char_p).value.decode(), flush=True)

glClearColor(0.1, 0.1, 0.15, 1.0)
glEnable(GL_DEPTH_TEST)
glMap2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, floats(*CTRL))
glEnable(GL_MAP2_VERTEX_3)
glEnable(GL_AUTO_NORMAL)
glMapGrid2f(20, 0.0, 1.0, 20, 0.0, 1.0)
glMap1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, floats(*CURVE))
glEnable(GL_MAP1_VERTEX_3)
glEnable(GL_LIGHTING)
glEnable(GL_LIGHT0)
glLightfv(GL_LIGHT0, GL_AMBIENT, floats(0.2, 0.2, 0.2, 1.0))
glLightfv(GL_LIGHT0, GL_POSITION, floats(0.0, 0.0, 2.0, 1.0))
glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, floats(0.6, 0.6, 0.6, 1.0))
glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, floats(1.0, 1.0, 1.0, 1.0))
glMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, floats(50.0))


@window.event
def on_resize(width, height):
    w, h = window.get_framebuffer_size()
    glViewport(0, 0, w, h)
    glMatrixMode(GL_PROJECTION)
    glLoadIdentity()
    glOrtho(-4.0, 4.0, -4.0 * h / w, 4.0 * h / w, -10.0, 10.0)
    glMatrixMode(GL_MODELVIEW)
    glLoadIdentity()
    return pyglet.event.EVENT_HANDLED


@window.event
def on_draw():
    on_resize(*window.get_size())  # pyglet's own on_resize may have run first
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


pyglet.clock.schedule_interval(lambda dt: None, 0.1)
pyglet.clock.schedule_once(lambda dt: pyglet.app.exit(), 3.0)
pyglet.app.run()
