/* wm_close.c: asks X window WINDOW (a number, as xdotool prints it) to close, as a window
 * manager's close button does: a WM_PROTOCOLS client message carrying WM_DELETE_WINDOW (ICCCM
 * 4.2.8.1). Xvfb runs no window manager; tools/freeglut_check/events.sh sends this instead.
 *   wm_close WINDOW */
#include <X11/Xlib.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    Display *d = XOpenDisplay(NULL);
    if (!d || argc < 2) return 1;
    XEvent e = {0};
    e.xclient.type = ClientMessage;
    e.xclient.window = strtoul(argv[1], NULL, 0);
    e.xclient.message_type = XInternAtom(d, "WM_PROTOCOLS", False);
    e.xclient.format = 32;
    e.xclient.data.l[0] = XInternAtom(d, "WM_DELETE_WINDOW", False);
    e.xclient.data.l[1] = CurrentTime;
    XSendEvent(d, e.xclient.window, False, NoEventMask, &e);
    XCloseDisplay(d);
    return 0;
}
