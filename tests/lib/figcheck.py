#!/usr/bin/env python3
"""tests/lib/figcheck.py: reads springsim's --figure files for tests/figure.sh.

  figcheck.py curves FILE.svg R,G,B        number of curves (stroked paths of more than
                                           two points) in that colour, in document order
  figcheck.py points FILE.svg R,G,B K      the points of the K-th such curve, "x y" lines
  figcheck.py dashed FILE.svg R,G,B        how many of those curves are dashed
  figcheck.py fit FILE.svg R,G,B K CSV TCOL YCOL
      the K-th curve against the CSV's columns: each point's page x, by the line through
      the first and last points (the first and last rows), is a row's time; page y is
      fitted to that row's value (y = c value + d, least squares). Prints "points rows
      max_residual c max_time_offset" (c < 0: up the page is up the axis; the offset, in
      points of the page, from the point to its row's time: cairo keeps 1/256 point)
  figcheck.py modefit FILE.svg R,G,B K CSV ROW
      the K-th curve against --modes' row ROW (0: mode 1): points at 0, the masses, N+1
      with shapes 0, x1..xN, 0; prints "points expected max_residual c max_offset" (the
      offset in points of the page)
  figcheck.py extent FILE.svg R,G,B K      "ymin ymax" of the K-th curve (page units)
  figcheck.py gridrows FILE.svg R,G,B      the page y of every horizontal segment of the
                                           paths in that colour (gridlines), one a line
  figcheck.py png FILE.png                 "WIDTH HEIGHT" from a well-formed PNG
  figcheck.py phasejump FILE.svg R,G,B     the largest step, in degrees, between two points
                                           joined by a line in the second curve of that
                                           colour (the phase panel: the last five gridlines,
                                           of 90 degrees each, give the scale)
  figcheck.py uprights FILE.svg R,G,B      number of upright strokes under 20 points long in
                                           that colour (a legend's mark for a line at one x)
  figcheck.py fills FILE.svg R,G,B         number of filled paths (markers) in that colour
  figcheck.py markers FILE.svg R,G,B       "N SMALLEST LARGEST": the markers (each filled
                                           sub-path) in that colour and their widths
  figcheck.py xticks FILE.pdf WORD         the numbers on the row above each x axis title
                                           holding WORD, one line per panel, left to right
  figcheck.py yticks FILE.pdf WORD         the numbers right-aligned left of each panel
                                           (the panels found by their x axis titles), one
                                           line per panel, top to bottom
  figcheck.py textsize FILE.pdf            the smallest text's size in points (the scale of
                                           the text matrices in the page's content)
  figcheck.py text FILE.pdf                the words, one line of the page a line
  figcheck.py overlaps FILE.pdf            every two words whose boxes meet (by more than
                                           0.2 pt each way), a line a pair: none on a page
                                           whose texts are apart
  figcheck.py cursors FILE.pdf             each cursor's lines of text ("t = ...", "x1 =
                                           ...", runs of words less than 6 pt apart on a
                                           line): "XMIN XMAX YMIN YMAX TEXT", then a line
                                           "plot LEFT": the right edge of the y tick labels
The PDF's words come from pdftotext -bbox (poppler-utils).
The SVG is parsed as XML; colours are cairo's rgb(p%,q%,r%) or rgb(r,g,b)."""
import csv
import re
import signal
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

SVG = '{http://www.w3.org/2000/svg}'


def stroke_of(el):
    style = el.get('style', '') + ';stroke:' + el.get('stroke', '')
    m = re.search(r'stroke:\s*rgb\(([^)]*)\)', style)
    if not m:
        return None
    parts = [p.strip() for p in m.group(1).split(',')]
    return tuple(round(float(p[:-1]) * 2.55) if p.endswith('%') else int(p) for p in parts)


def dashed(el):
    return 'stroke-dasharray' in el.get('style', '') or el.get('stroke-dasharray') is not None


def path_points(d):
    """The points of a path's first sub-path (its line: markers come after it), of
    absolute M, L and C commands as cairo writes them."""
    toks = re.findall(r'[MLCZmlcz]|-?[0-9.]+(?:e-?[0-9]+)?', d)
    pts, cmd, nums = [], None, []
    for t in toks:
        if t.isalpha():
            if t == 'M' and pts:
                break
            cmd, nums = t, []
            continue
        nums.append(float(t))
        if cmd in ('M', 'L') and len(nums) == 2:
            pts.append(tuple(nums))
            nums = []
        elif cmd == 'C' and len(nums) == 6:
            pts.append(tuple(nums[4:]))
            nums = []
    return pts


def transformed(el, pts):
    """pts under the element's transform="matrix(a,b,c,d,e,f)", as cairo writes it."""
    m = re.search(r'matrix\(([^)]*)\)', el.get('transform', ''))
    if not m:
        return pts
    a, b, c, d, e, f = (float(v) for v in m.group(1).split(','))
    return [(a * x + c * y + e, b * x + d * y + f) for x, y in pts]


def curves(path, rgb):
    root = ET.parse(path).getroot()
    out = []
    for el in root.iter(SVG + 'path'):
        if stroke_of(el) != rgb:
            continue
        pts = transformed(el, path_points(el.get('d', '')))
        if len(pts) > 2:
            out.append((el, pts))
    return out


def fit(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    a = sxy / sxx
    b = my - a * mx
    return a, b, max(abs(a * x + b - y) for x, y in zip(xs, ys))


def png_size(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise SystemExit('not a PNG')
    pos, size, idat = 8, None, b''
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if zlib.crc32(kind + body) != struct.unpack('>I', data[pos + 8 + n:pos + 12 + n])[0]:
            raise SystemExit('bad CRC in ' + kind.decode())
        if kind == b'IHDR':
            size = struct.unpack('>II', body[:8])
        elif kind == b'IDAT':
            idat += body
        elif kind == b'IEND':
            break
        pos += 12 + n
    zlib.decompress(idat)  # the pixels decompress whole
    return size


def pdf_words(path):
    """(xMin, yMin, xMax, yMax, text) of every word of the PDF's first page."""
    import subprocess
    out = subprocess.run(['pdftotext', '-bbox', path, '-'], capture_output=True, check=True,
                         text=True).stdout
    words = []
    for m in re.finditer(r'<word xMin="([^"]*)" yMin="([^"]*)" xMax="([^"]*)" yMax="([^"]*)">'
                         r'([^<]*)</word>', out):
        words.append(tuple(float(m.group(i)) for i in range(1, 5)) + (m.group(5),))
    return words


def is_number(t):
    return re.fullmatch(r'-?[0-9.]+(e-?[0-9]+)?', t) is not None


def y_column(nums):
    """The right edge the y tick labels are aligned on: the one most numbers share."""
    return max((w[2] for w in nums), key=lambda x: sum(1 for v in nums if abs(v[2] - x) < 0.5))


def axis_titles(words, word):
    """The top of each x axis title holding word, top to bottom (one per panel)."""
    return sorted(set(round(w[1], 2) for w in words if w[4] == word))


def text_runs(words):
    """The words in runs: on one line (the same top), less than 6 pt apart; each run
    (xMin, yMin, xMax, yMax, text)."""
    rows, runs = {}, []
    for w in words:
        rows.setdefault(round(w[1], 1), []).append(w)
    for y in sorted(rows):
        run = None
        for w in sorted(rows[y]):
            if run and w[0] - run[2] < 6.0:
                run = (run[0], min(run[1], w[1]), w[2], max(run[3], w[3]), run[4] + ' ' + w[4])
            else:
                if run:
                    runs.append(run)
                run = w
        runs.append(run)
    return runs


def text_command(cmd, words):
    """overlaps and cursors: where the texts on a page lie."""
    if cmd == 'overlaps':
        for i, a in enumerate(words):
            for b in words[i + 1:]:
                if a[0] + 0.2 < b[2] and b[0] + 0.2 < a[2] and a[1] + 0.2 < b[3] and b[1] + 0.2 < a[3]:
                    print('%s [%.1f..%.1f, %.1f..%.1f] meets %s [%.1f..%.1f, %.1f..%.1f]' %
                          (a[4], a[0], a[2], a[1], a[3], b[4], b[0], b[2], b[1], b[3]))
    elif cmd == 'cursors':
        for r in text_runs(words):
            if re.match(r'(t|[xva][0-9]+) = ', r[4]):
                print('%.1f %.1f %.1f %.1f %s' % r)
        print('plot %.1f' % y_column([w for w in words if is_number(w[4])]))


def pdf_command(cmd, path, arg):
    words = pdf_words(path)
    if cmd in ('overlaps', 'cursors'):
        text_command(cmd, words)
    elif cmd == 'textsize':
        # The size of every run of text: its text matrix's scale (cairo sets the font at
        # size 1 and scales by Tm, under a page transform of scale 1).
        data = open(path, 'rb').read()
        sizes = []
        for m in re.finditer(rb'stream\r?\n(.*?)endstream', data, re.S):
            try:
                body = zlib.decompress(m.group(1)).decode('latin1')
            except zlib.error:
                continue
            for t in re.finditer(r'(-?[0-9.]+) (-?[0-9.]+) (-?[0-9.]+) (-?[0-9.]+) '
                                 r'-?[0-9.]+ -?[0-9.]+ Tm', body):
                a, b = float(t.group(1)), float(t.group(2))
                sizes.append((a * a + b * b) ** 0.5)
        print('%.2f' % min(sizes))
    elif cmd == 'text':
        rows = {}
        for w in words:
            rows.setdefault(round(w[1], 1), []).append(w)
        for y in sorted(rows):
            print(' '.join(w[4] for w in sorted(rows[y])))
    elif cmd == 'xticks':
        nums = [w for w in words if is_number(w[4])]
        right = y_column(nums)
        for top in axis_titles(words, arg):
            row = sorted((w for w in nums if top - 16 < w[3] <= top + 0.5 and
                          abs(w[2] - right) >= 1.0), key=lambda w: w[0])
            print(' '.join(w[4] for w in row))
    elif cmd == 'yticks':
        above = -1e9
        nums = [w for w in words if is_number(w[4])]
        right = y_column(nums)
        for top in axis_titles(words, arg):
            col = sorted((w for w in nums if abs(w[2] - right) < 1.0 and above < w[1] < top - 16),
                         key=lambda w: w[1])
            print(' '.join(w[4] for w in col))
            above = top


def sub_paths(d):
    """Every sub-path of a path's M and L commands (a line broken into pieces)."""
    toks = re.findall(r'[MLCZmlcz]|-?[0-9.]+(?:e-?[0-9]+)?', d)
    out, cmd, nums = [], None, []
    for t in toks:
        if t.isalpha():
            cmd, nums = t, []
            if t == 'M':
                out.append([])
            continue
        nums.append(float(t))
        if cmd in ('M', 'L') and len(nums) == 2:
            out[-1].append(tuple(nums))
            nums = []
        elif cmd == 'C' and len(nums) == 6:
            out[-1].append(tuple(nums[4:]))
            nums = []
    return out


def main():
    cmd = sys.argv[1]
    if cmd == 'png':
        print('%d %d' % png_size(sys.argv[2]))
        return
    if cmd in ('textsize', 'text', 'xticks', 'yticks', 'overlaps', 'cursors'):
        pdf_command(cmd, sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else None)
        return
    rgb = tuple(int(v) for v in sys.argv[3].split(','))
    found = curves(sys.argv[2], rgb)
    if cmd == 'gridrows':
        root = ET.parse(sys.argv[2]).getroot()
        ys = set()
        for el in root.iter(SVG + 'path'):
            if stroke_of(el) != rgb:
                continue
            toks = re.findall(r'[ML]|-?[0-9.]+', el.get('d', ''))
            nums = [float(t) for t in toks if t not in ('M', 'L')]
            pts = transformed(el, list(zip(nums[0::2], nums[1::2])))
            for a, b in zip(pts[0::2], pts[1::2]):
                if abs(a[1] - b[1]) < 1e-6 and abs(a[0] - b[0]) > 1:
                    ys.add(round(a[1], 3))
        for y in sorted(ys):
            print(y)
        return
    if cmd in ('fills', 'markers'):
        root = ET.parse(sys.argv[2]).getroot()
        n, widths = 0, []
        for el in root.iter(SVG + 'path'):
            style = el.get('style', '') + ';fill:' + el.get('fill', '')
            m = re.search(r'fill:\s*rgb\(([^)]*)\)', style)
            if m:
                parts = [p.strip() for p in m.group(1).split(',')]
                c = tuple(round(float(p[:-1]) * 2.55) if p.endswith('%') else int(p)
                          for p in parts)
                filled = c == rgb and 'stroke:' not in el.get('style', '').replace('stroke:none', '')
                n += filled
                for sp in sub_paths(el.get('d', '')) if filled else []:
                    pts = transformed(el, sp)
                    widths.append(max(p[0] for p in pts) - min(p[0] for p in pts))
        if cmd == 'fills':
            print(n)
        else:
            print('%d %.2f %.2f' % (len(widths), min(widths or [0]), max(widths or [0])))
        return
    if cmd == 'uprights':
        n = 0
        for el in ET.parse(sys.argv[2]).getroot().iter(SVG + 'path'):
            if stroke_of(el) == rgb:
                for sp in sub_paths(el.get('d', '')):
                    pts = transformed(el, sp)
                    n += (len(pts) == 2 and abs(pts[0][0] - pts[1][0]) < 1e-6 and
                          0 < abs(pts[0][1] - pts[1][1]) < 20)
        print(n)
        return
    if cmd == 'phasejump':
        root = ET.parse(sys.argv[2]).getroot()
        grid = tuple(int(v) for v in sys.argv[4].split(','))
        ys = []
        for el in root.iter(SVG + 'path'):
            if stroke_of(el) != grid:
                continue
            for sp in sub_paths(el.get('d', '')):
                pts = transformed(el, sp)
                if len(pts) == 2 and abs(pts[0][1] - pts[1][1]) < 1e-6:
                    ys.append(pts[0][1])
        rows = sorted(set(round(y, 3) for y in ys))[-5:]
        deg = 90.0 / ((rows[-1] - rows[0]) / 4.0)
        lines = [el for el in root.iter(SVG + 'path') if stroke_of(el) == rgb]
        el = lines[-1]
        jump = 0.0
        for sp in sub_paths(el.get('d', '')):
            pts = transformed(el, sp)
            for a, b in zip(pts, pts[1:]):
                jump = max(jump, abs(a[1] - b[1]) * deg)
        print('%.1f' % jump)
        return
    if cmd == 'curves':
        print(len(found))
    elif cmd == 'dashed':
        print(sum(1 for el, _ in found if dashed(el)))
    elif cmd == 'extent':
        pts = found[int(sys.argv[4])][1]
        print(min(p[1] for p in pts), max(p[1] for p in pts))
    elif cmd == 'points':
        for x, y in found[int(sys.argv[4])][1]:
            print(x, y)
    elif cmd == 'fit':
        pts = found[int(sys.argv[4])][1]
        with open(sys.argv[5]) as f:
            rows = [r for r in csv.DictReader(line for line in f if not line.startswith('#'))]
        t = [float(r[sys.argv[6]]) for r in rows]
        v = [float(r[sys.argv[7]]) for r in rows]
        # cairo merges a run of segments in one direction into one, so a point is a row
        # but not every row is a point: the first and last are, and they fix the time
        # axis; every point must then land on a row's time.
        a = (pts[-1][0] - pts[0][0]) / (t[-1] - t[0])
        spacing = (t[-1] - t[0]) / (len(t) - 1)
        xs, ys, off = [], [], 0.0
        for px, py in pts:
            tt = t[0] + (px - pts[0][0]) / a
            k = min(range(len(t)), key=lambda i: abs(t[i] - tt)) if len(t) < 5000 else \
                int(round((tt - t[0]) / spacing))
            off = max(off, abs(t[k] - tt) * abs(a))
            xs.append(v[k])
            ys.append(py)
        c, _, ry = fit(xs, ys)
        print('%d %d %.6g %.6g %.3g' % (len(pts), len(rows), ry, c, off))
    elif cmd == 'modefit':
        pts = found[int(sys.argv[4])][1]
        with open(sys.argv[5]) as f:
            rows = [r for r in csv.DictReader(line for line in f if not line.startswith('#'))]
        row = rows[int(sys.argv[6])]
        n = sum(1 for k in row if re.fullmatch(r'x[0-9]+', k))
        want = [0.0] + [float(row['x%d' % (i + 1)]) for i in range(n)] + [0.0]
        # As for fit: the first and last points are the walls, every point a mass.
        a = (pts[-1][0] - pts[0][0]) / (n + 1)
        idx = [(px - pts[0][0]) / a for px, _ in pts]
        off = max(abs(i - round(i)) for i in idx) * abs(a)
        c, _, ry = fit([want[int(round(i))] for i in idx], [p[1] for p in pts])
        print('%d %d %.6g %.6g %.3g' % (len(pts), len(want), ry, c, off))


signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # a reader that stops early (head) is no error
main()
