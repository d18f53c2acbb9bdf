#!/usr/bin/python3
"""tests/lib/xfeed.py: runs a program in a pseudo-terminal inside a real terminal (xterm),
passing the terminal's bytes both ways, typing KEYS and keeping what the program wrote
in OUT and what the terminal answered in OUT.in, its window size in DIR/winsize.

  xfeed.py DIR KEYS PROGRAM [ARGS...]

KEYS are typed one every 0.3 s from 2 s on; '~' waits a second; '!' copies what was
written so far to DIR/out.shot, writes DIR/ready and waits until DIR/go exists (the
screen is still for a screenshot). OUT is DIR/out."""
import fcntl
import os
import pty
import select
import struct
import sys
import termios
import time
import tty

d, keys, args = sys.argv[1], sys.argv[2], sys.argv[3:]
pid, fd = pty.fork()
if pid == 0:
    os.execvp(args[0], args)
ws = fcntl.ioctl(0, termios.TIOCGWINSZ, b'\0' * 8)
fcntl.ioctl(fd, termios.TIOCSWINSZ, ws)
with open(d + '/winsize', 'w') as f:  # rows cols xpixel ypixel
    f.write('%d %d %d %d\n' % struct.unpack('HHHH', ws))
old = termios.tcgetattr(0)
tty.setraw(0)
out, ins = open(d + '/out', 'wb'), open(d + '/out.in', 'wb')
nxt, k = time.time() + 2.0, 0
try:
    while True:
        if k < len(keys) and time.time() >= nxt:
            c = keys[k]
            k += 1
            nxt = time.time() + 0.3
            if c == '~':
                nxt = time.time() + 1.0
            elif c == '!':
                out.flush()
                with open(d + '/out', 'rb') as f, open(d + '/out.shot', 'wb') as g:
                    g.write(f.read())
                open(d + '/ready', 'w').close()
                while not os.path.exists(d + '/go'):
                    time.sleep(0.1)
            else:
                os.write(fd, c.encode())
        r, _, _ = select.select([0, fd], [], [], 0.05)
        if fd in r:
            try:
                b = os.read(fd, 65536)
            except OSError:
                break
            if not b:
                break
            out.write(b)
            os.write(1, b)
        if 0 in r:
            b = os.read(0, 4096)
            ins.write(b)
            os.write(fd, b)
finally:
    termios.tcsetattr(0, termios.TCSADRAIN, old)
    out.close()
    ins.close()
