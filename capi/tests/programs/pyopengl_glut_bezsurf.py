"""PyOpenGL GLUT: the bezsurf scene (bezsurf_scene.py) in a 400x400 GLUT_DOUBLE | GLUT_RGB |
GLUT_DEPTH window titled "bezsurf glut", redisplayed every 100 ms by a timer; exits after 3 s.
   python3 pyopengl_glut_bezsurf.py"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from OpenGL.GLUT import *

import bezsurf_scene as scene

start = time.monotonic()
reported = False


def display():
    global reported
    if not reported:
        scene.report()
        reported = True
    scene.display()
    glutSwapBuffers()


def tick(value):
    if time.monotonic() - start >= 3.0:
        sys.stdout.flush()
        os._exit(0)
    glutPostRedisplay()
    glutTimerFunc(100, tick, 0)


glutInit(sys.argv)
glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH)
glutInitWindowSize(scene.SIZE, scene.SIZE)
glutInitWindowPosition(0, 0)
glutCreateWindow(b"bezsurf glut")
scene.init()
glutDisplayFunc(display)
glutReshapeFunc(scene.reshape)
glutTimerFunc(100, tick, 0)
glutMainLoop()
