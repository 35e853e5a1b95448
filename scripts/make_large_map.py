#!/usr/bin/env python3
"""Writes a large map_server map (binary PGM + YAML): a grid of rooms joined by doors.

Usage: scripts/make_large_map.py OUT.yaml --pixels 10000 [--resolution 0.05] [--room-m 8]

The map is PIXELS x PIXELS pixels: square rooms of ROOM_M metres with 0.2 m walls and a
1 m door in the middle of each wall, inside a solid border. Made for measuring roomscout's
memory and time on large inputs (docs/cli.md, "Large maps"); no dependency beyond Python.
"""
import argparse
import os

FREE, WALL = 254, 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("yaml")
    parser.add_argument("--pixels", type=int, required=True, help="width and height [pixels]")
    parser.add_argument("--resolution", type=float, default=0.05, help="[m/pixel]")
    parser.add_argument("--room-m", type=float, default=8.0, help="room side [m]")
    args = parser.parse_args()

    n = args.pixels
    period = max(8, round(args.room_m / args.resolution))  # pixels from wall to wall
    wall = max(1, round(0.2 / args.resolution))
    door = max(2, round(1.0 / args.resolution))
    door_lo = (period - door) // 2

    def on_wall(i):
        return i < wall or i >= n - wall or (i % period) < wall

    def in_door(i):
        return door_lo <= i % period < door_lo + door and not (i < wall or i >= n - wall)

    # Three kinds of row: inside rooms (vertical walls only), on a horizontal wall with its
    # doors, and on the border / where a horizontal wall meets a door column.
    room_row = bytes(WALL if on_wall(x) else FREE for x in range(n))
    wall_row = bytes(FREE if (in_door(x) and not on_wall(x)) else WALL for x in range(n))
    solid_row = bytes([WALL]) * n
    door_row = bytes(FREE if (not on_wall(x) or in_door(x)) else WALL for x in range(n))

    base = os.path.splitext(args.yaml)[0]
    pgm = base + ".pgm"
    with open(pgm, "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (n, n))
        for y in range(n):
            if y < wall or y >= n - wall:
                f.write(solid_row)
            elif on_wall(y):
                f.write(wall_row)
            elif in_door(y):
                f.write(door_row)
            else:
                f.write(room_row)
    with open(args.yaml, "w") as f:
        f.write("image: %s\nresolution: %g\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                "occupied_thresh: 0.65\nfree_thresh: 0.196\n" % (os.path.basename(pgm),
                                                                  args.resolution))


if __name__ == "__main__":
    main()
