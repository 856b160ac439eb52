"""pygame + PyOpenGL: the bezsurf scene (bezsurf_scene.py) in a 400x400 DOUBLEBUF | OPENGL
window titled "bezsurf pygame", redrawn every 100 ms with pygame.display.flip(); exits after
3 s.   python3 pygame_bezsurf.py"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
os.environ.setdefault("SDL_VIDEO_WINDOW_POS", "0,0")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

import pygame
from pygame.locals import DOUBLEBUF, OPENGL, QUIT, KEYDOWN

import bezsurf_scene as scene

pygame.display.init()
pygame.display.gl_set_attribute(pygame.GL_DEPTH_SIZE, 16)
pygame.display.set_caption("bezsurf pygame")
pygame.display.set_mode((scene.SIZE, scene.SIZE), DOUBLEBUF | OPENGL)
scene.report()
scene.init()
start = pygame.time.get_ticks()
running = True
while running and pygame.time.get_ticks() - start < 3000:
    for event in pygame.event.get():
        if event.type in (QUIT, KEYDOWN):
            running = False
    scene.reshape(scene.SIZE, scene.SIZE)
    scene.display()
    pygame.display.flip()
    pygame.time.wait(100)
pygame.quit()
