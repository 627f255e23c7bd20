#!/usr/bin/env python3
"""Writes a geological model moved, turned, scaled or mirrored, to try the
mesher on the same geology in other coordinates (a model that meshes only in
its own frame has a bug, see bench/README.md, sessions 27, 28 and 35).

Reads GOCAD Model3d (.ml) and TSurf (.ts) files and multi-body OBJ files. It
rewrites the VRTX/PVRTX lines, the three key-triangle lines after each TFACE
of a Model3d, and OBJ 'v' lines, and copies every other line as it is. So
triangles, patches and regions are the same, and only coordinates change
(mirroring turns every triangle over: the mesher takes the sides from the
geometry and says so).

  bench/transform_model.py IN OUT [--rotate-z DEG] [--scale S] [--mirror-x]
                                  [--translate X Y Z]

The operations apply in that order: rotation about the vertical through the
origin, scaling, mirroring in x, translation. Each coordinate is written with
repr(), the shortest text that reads back the same double.
"""
import argparse
import math
import sys


def transform(args):
    c, s = math.cos(math.radians(args.rotate_z)), math.sin(math.radians(args.rotate_z))
    tx, ty, tz = args.translate

    def apply(x, y, z):
        x, y = c * x - s * y, s * x + c * y
        x, y, z = args.scale * x, args.scale * y, args.scale * z
        if args.mirror_x:
            x = -x
        return x + tx, y + ty, z + tz
    return apply


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    p.add_argument('input')
    p.add_argument('output')
    p.add_argument('--rotate-z', type=float, default=0., metavar='DEG')
    p.add_argument('--scale', type=float, default=1.)
    p.add_argument('--mirror-x', action='store_true')
    p.add_argument('--translate', type=float, nargs=3, default=(0., 0., 0.), metavar=('X', 'Y', 'Z'))
    args = p.parse_args()
    if not args.scale > 0.:
        sys.exit('transform_model.py: --scale must be positive')
    apply = transform(args)
    is_obj = args.input.lower().endswith('.obj')
    out = []
    key_lines = 0  # Model3d: coordinate lines left in the current TFACE's key triangle
    with open(args.input, errors='replace') as f:
        for number, line in enumerate(f, 1):
            t = line.split()
            try:
                if is_obj and t and t[0] == 'v':
                    out.append('v %r %r %r\n' % apply(*map(float, t[1:4])))
                    continue
                if t and t[0] in ('VRTX', 'PVRTX'):
                    xyz = apply(*map(float, t[2:5]))
                    out.append(' '.join([t[0], t[1]] + [repr(v) for v in xyz] + t[5:]) + '\n')
                    continue
                if t and t[0] == 'TFACE':
                    key_lines = 3
                    out.append(line)
                    continue
                if key_lines and len(t) == 3:
                    key_lines -= 1
                    out.append('  ' + ' '.join(repr(v) for v in apply(*map(float, t))) + '\n')
                    continue
            except ValueError:
                sys.exit('transform_model.py: %s:%d: not a coordinate line: %s' % (args.input, number, line.strip()))
            key_lines = 0
            out.append(line)
    with open(args.output, 'w') as f:
        f.write(''.join(out))


if __name__ == '__main__':
    main()
