#!/usr/bin/python3
"""tests/lib/screen.py: what a terminal showed, from the bytes a program wrote to it
(pixterm's OUT), by pyte's terminal emulator, its images taken out first (sixel and
kitty escapes; tests/sixelcheck.c reads those).

  screen.py show OUT COLS ROWS [UPTO]
      the screen, one line a row, as it was after the UPTO-th image (default: the last;
      "end": after everything written)
  screen.py chart OUT COLS ROWS TITLE [UPTO]
      the chart whose title holds TITLE: "AY AX AW AH" (its drawing area: the first row
      and column, 1-based as a CSI H counts them, and its size in cells), then one line
      "VALUE ROW" for each y tick label (ROW 1-based)
"""
import re
import sys

import pyte


def screen(path, cols, rows, upto=None):
    data = open(path, 'rb').read()
    ends = [m.end() for m in re.finditer(rb'\x1bP.*?\x1b\\|\x1b_Ga=T.*?\x1b\\(?!\x1b_Gm)',
                                         data, flags=re.S)]
    if ends and upto != 'end':
        data = data[:ends[-1] if upto is None else ends[upto - 1]]
    data = re.sub(rb'\x1bP.*?\x1b\\', b'', data, flags=re.S)
    data = re.sub(rb'\x1b_.*?\x1b\\', b'', data, flags=re.S)
    sc = pyte.Screen(cols, rows)
    pyte.ByteStream(sc).feed(data)
    return sc.display


def chart(lines, title):
    top = next(i for i, l in enumerate(lines) if title in l)
    labels = []
    axis = None
    for i in range(top + 1, len(lines)):
        m = re.match(r'^│ *(-?[0-9.e]+)┤', lines[i])
        if m:
            labels.append((m.group(1), i + 1))
            axis = lines[i].index('┤')
        if lines[i].lstrip('│ ').startswith('└') or '└─┬' in lines[i] or '└┬' in lines[i]:
            bottom = i
            break
    right = lines[top + 1].index('│', axis + 1)
    ay, ax = top + 2, axis + 2
    print(ay, ax, right - axis - 1, bottom - top - 1)
    for v, r in labels:
        print(v, r)


def main():
    cmd, path, cols, rows = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    if cmd == 'show':
        upto = sys.argv[5] if len(sys.argv) > 5 else None
        upto = upto if upto in (None, 'end') else int(upto)
        print('\n'.join(screen(path, cols, rows, upto)))
    elif cmd == 'chart':
        upto = sys.argv[6] if len(sys.argv) > 6 else None
        upto = upto if upto in (None, 'end') else int(upto)
        chart(screen(path, cols, rows, upto), sys.argv[5])


if __name__ == '__main__':
    main()
