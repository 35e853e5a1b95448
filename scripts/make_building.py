#!/usr/bin/env python3
"""Writes a generated indoor world (roomscout world YAML): a large office floor or house block.

Usage: scripts/make_building.py OUT.yaml --kind office|house --area-m2 A [--seed S] [--name NAME]

The building is a rectangle. Rows of rooms line the outer walls; inside them a ring of
corridors runs round the floor, with east-west corridors between double rows of rooms and
north-south corridors joining them, so the floor is one connected space (small buildings get
one corridor with a row of rooms on each side). Every room opens onto a corridor (an ensuite,
a walk-in closet or an archive onto the room in front of it, an open kitchen onto the living
room beside it) through a door 0.8-1.0 m wide or an opening 1.2-2 m wide.

  office: corridors 2-3 m wide; cellular offices 3-6 m wide and 4-6 m deep, meeting rooms,
          focus rooms, manager offices with an archive, kitchens, toilets, print, server and
          storage rooms, open-plan areas and training rooms up to 150 m2 (1.5-2 m openings).
  house:  a large house / apartment block: hallways 1.4-1.8 m wide off which open bedrooms
          (some with an ensuite or a walk-in closet), living rooms (1.6-2 m openings) with an
          open kitchen beside them, dining rooms, studies, bathrooms, WCs, storage and laundry
          rooms; rooms 6-30 m2, living rooms up to about 36 m2.

Outer walls 0.2 m, corridor walls 0.15 m, partitions 0.1 m; wall segments run past their
corners by half the crossing wall's thickness so corners are solid. Every room is listed under
`rooms:` (the ground truth of room segmentation). The free floor area (inside the outer walls,
minus the walls, doorways cut out) is computed exactly from the wall rectangles, whose edges
all lie on roomscout's 0.025 m world raster; it is within 10 % (usually 2 %) of A and is
stated in OUT's header. Start pose: the middle of the southern corridor. The same seed gives
the same building. The largest A fits roomscout's grid limit (kMaxGridCells = 25 000 000
cells of the 0.025 m world raster, src/roomscout/core/grid_limits.hpp): about 14 000 m2.
No dependency beyond Python 3.
"""
import argparse
import bisect
import math
import os
import random
import re
import shlex
import sys
from collections import defaultdict

# All geometry is in integer millimetres. Rooms lie on a 0.1 m lattice, door centres on 0.05 m.
GRID = 100
DOOR_SNAP = 50
DOOR_MARGIN = 300  # door centre at least width/2 + this from the end of its wall run [mm]
OUTER_WALL, CORRIDOR_WALL, PARTITION = 200, 150, 100

# roomscout's limits (src/roomscout/core/grid_limits.hpp, src/roomscout/sim/world_model.cpp):
# the world raster is 0.025 m, padded by 0.5 m, its origin on a multiple of 0.05 m.
MAX_GRID_CELLS = 25_000_000
RASTER_MM = 25
RASTER_PAD_MM = 500
MIN_AREA_M2 = 200.0
AREA_TOLERANCE = 0.10  # the promise: free floor within 10 % of --area-m2
AREA_GOAL = 0.015      # what the size search aims for

KINDS = {
    "office": {
        "corridor": (2.0, 3.0),    # corridor width [m]
        "perimeter": (4.5, 6.0),   # depth of the rows along the outer walls [m]
        "row": (4.0, 6.0),         # depth of each row of a double row between corridors [m]
        "span": (28.0, 40.0),      # length of a block between north-south corridors [m]
        "wall_height": 2.8,
        "free_fraction": 0.93,     # free floor / gross floor, first guess
        "max_area": 14000,         # largest --area-m2 (checked against the grid limit below)
        "corridor_name": "corridor",
        "title": "office floor",
    },
    "house": {
        "corridor": (1.4, 1.8),
        "perimeter": (3.6, 4.4),
        "row": (3.2, 5.0),
        "span": (18.0, 26.0),
        "wall_height": 2.5,
        "free_fraction": 0.90,
        "max_area": 13500,
        "corridor_name": "hallway",
        "title": "house block",
    },
}


class GenerationError(Exception):
    pass


def snap(value_m, step=GRID):
    """Metres to millimetres on the lattice."""
    return int(round(value_m * 1000.0 / step)) * step


def fmt(mm):
    """Millimetres as metres, shortest exact form: 12350 -> '12.35'."""
    text = ("%.3f" % (mm / 1000.0)).rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def raster_cells(width_mm, height_mm):
    """Cells of roomscout's world raster for a building whose outer wall centre lines are
    x 0..width, y 0..height (0.2 m outer walls running 0.1 m past the corners)."""
    lo, hi_x, hi_y = -200, width_mm + 200, height_mm + 200
    origin = math.floor((lo - RASTER_PAD_MM) / 50.0) * 50
    nx = math.ceil((hi_x + RASTER_PAD_MM - origin) / RASTER_MM)
    ny = math.ceil((hi_y + RASTER_PAD_MM - origin) / RASTER_MM)
    return nx * ny


def largest_side_mm():
    """Side of the largest square building whose raster fits kMaxGridCells."""
    side = int(math.sqrt(MAX_GRID_CELLS)) * RASTER_MM
    while raster_cells(side, side) > MAX_GRID_CELLS:
        side -= GRID
    return side - side % GRID


def quantize(lengths_m, total_mm):
    """Lengths scaled to sum to total_mm, each on the lattice (cumulative rounding)."""
    s = sum(lengths_m)
    out, cum, prev = [], 0.0, 0
    for i, length in enumerate(lengths_m):
        cum += length
        pos = total_mm if i == len(lengths_m) - 1 else snap(cum / s * total_mm / 1000.0)
        out.append(pos - prev)
        prev = pos
    return out


# --------------------------------------------------------------------------------------------
# Units: what one stretch of a row of rooms holds. A unit has one or more columns (widths in
# metres) and, given their final widths and the row depth, makes rooms in row coordinates
# (u along the row, v depth from the corridor side) and door requests.


class Unit:
    def __init__(self, columns, build):
        self.columns = columns  # widths [m]
        self.build = build      # build(cols_mm, depth_mm) -> (rooms, doors)

    @property
    def width(self):
        return sum(self.columns)


def single(kind, doors, style="corner"):
    """One room the row's full depth, with doors (list of widths [m]) onto the corridor."""
    def build(cols, depth):
        return [(kind, 0, cols[0], 0, depth)], [(0, "C", doors, style)]
    return build


def front_back(front_kind, back_kind, back_depth_m, front_door, back_door):
    """A room on the corridor and a smaller one behind it, entered from the front room."""
    def build(cols, depth):
        split = depth - snap(back_depth_m)
        return ([(front_kind, 0, cols[0], 0, split), (back_kind, 0, cols[0], split, depth)],
                [(0, "C", [front_door], "corner"), (1, 0, [back_door], "corner")])
    return build


def pick(rng, choices):
    return choices[rng.randrange(len(choices))]


def office_unit(rng, depth_m, remaining_m):
    """One unit of an office row; None when nothing fits into remaining_m."""
    def width_in(lo, hi):
        return rng.uniform(lo, min(hi, remaining_m))

    options = [("office", 52, 3.0, 6.0), ("meeting_room", 11, 5.0, min(8.0, 48.0 / depth_m)),
               ("focus_room", 6, 2.2, 3.0), ("wc", 5, 2.4, 3.6), ("storage", 5, 2.0, 3.0),
               ("kitchen", 4, 4.0, 6.0), ("print_room", 3, 2.5, 3.5),
               ("server_room", 2, 2.5, 3.5)]
    if depth_m >= 5.0:
        options.append(("manager_office", 5, 4.0, 6.0))
    if depth_m >= 4.5:
        options.append(("open_plan", 7, 8.0, min(20.0, 150.0 / depth_m)))
    options = [o for o in options if o[2] <= remaining_m and o[2] <= o[3]]
    if not options:
        return None
    kind, lo, hi = weighted(rng, options)
    w = width_in(lo, hi)
    if kind == "office":
        return Unit([w], single("office", [pick(rng, [0.9, 0.9, 1.0])]))
    if kind == "meeting_room":
        return Unit([w], single("meeting_room", [pick(rng, [1.0, 1.6])]))
    if kind in ("focus_room", "wc", "print_room", "server_room"):
        return Unit([w], single(kind, [0.9]))
    if kind == "storage":
        return Unit([w], single("storage", [pick(rng, [0.8, 0.9])]))
    if kind == "kitchen":
        return Unit([w], single("kitchen", [1.6], "center"))
    if kind == "manager_office":
        return Unit([w], front_back("manager_office", "archive", rng.uniform(1.8, 2.4), 1.0, 0.8))
    # open plan: one opening, two when long
    n = 2 if w >= 11.0 else 1
    return Unit([w], single("open_plan", [pick(rng, [1.5, 1.8, 2.0]) for _ in range(n)],
                            "center"))


def house_unit(rng, depth_m, remaining_m):
    """One unit of a house row; None when nothing fits into remaining_m."""
    d = depth_m
    min6 = 6.4 / d  # narrowest room of 6 m2 (with room for rounding)
    options = [("bedroom", 30, 3.0, min(4.6, 26.0 / d)), ("living", 15, 4.8 + 2.6, 0),
               ("dining_room", 6, 3.5, min(5.0, 28.0 / d)),
               ("bathroom", 12, max(2.2, min6), 3.2),
               ("wc", 5, max(1.6, min6), max(2.2, min6 + 0.3)),
               ("study", 8, max(2.6, min6), 3.8),
               ("storage", 5, max(1.9, min6), max(2.6, min6 + 0.3)),
               ("laundry", 4, max(2.0, min6), max(3.0, min6 + 0.3))]
    options = [o for o in options if o[2] <= remaining_m and (o[0] == "living" or o[2] <= o[3])]
    if not options:
        return None
    kind, lo, hi = weighted(rng, options)
    if kind == "living":
        wl = rng.uniform(4.8, max(4.8, min(6.5, 34.0 / d, remaining_m - 2.6)))
        wk = rng.uniform(2.6, max(2.6, min(3.6, remaining_m - wl)))
        kitchen_left = rng.random() < 0.5
        living_door = pick(rng, [1.6, 1.8, 2.0])
        kitchen_door = pick(rng, [1.2, 1.4, 1.6])

        def build(cols, depth):
            if kitchen_left:
                rooms = [("living_room", cols[0], cols[0] + cols[1], 0, depth),
                         ("kitchen", 0, cols[0], 0, depth)]
            else:
                rooms = [("living_room", 0, cols[0], 0, depth),
                         ("kitchen", cols[0], cols[0] + cols[1], 0, depth)]
            return rooms, [(0, "C", [living_door], "center"), (1, 0, [kitchen_door], "center")]
        return Unit([wk, wl] if kitchen_left else [wl, wk], build)
    w = rng.uniform(lo, min(hi, remaining_m))
    if kind == "bedroom":
        door = pick(rng, [0.8, 0.9, 0.9])
        if d >= 4.6 and rng.random() < 0.45:
            back = pick(rng, ["ensuite", "ensuite", "walk_in_closet"])
            return Unit([w], front_back("bedroom", back, rng.uniform(2.0, min(2.4, d - 2.6)),
                                        door, 0.8))
        return Unit([w], single("bedroom", [door]))
    if kind == "dining_room":
        return Unit([w], single("dining_room", [pick(rng, [1.5, 1.6, 1.8])], "center"))
    if kind == "study":
        return Unit([w], single("study", [0.9]))
    return Unit([w], single(kind, [0.8]))


def weighted(rng, options):
    total = sum(o[1] for o in options)
    x = rng.uniform(0, total)
    for name, weight, lo, hi in options:
        x -= weight
        if x <= 0:
            return name, lo, hi
    name, _, lo, hi = options[-1]
    return name, lo, hi


UNIT_MAKERS = {"office": office_unit, "house": house_unit}
MIN_UNIT_M = {"office": 2.0, "house": 2.0}


# --------------------------------------------------------------------------------------------
# The plan: rooms as rectangles tiling the building, and the doors each room asks for.


class Room:
    def __init__(self, kind, rect, corridor):
        self.kind = kind
        self.rect = rect  # (x0, y0, x1, y1) [mm]
        self.corridor = corridor
        self.name = None

    @property
    def area_m2(self):
        x0, y0, x1, y1 = self.rect
        return (x1 - x0) * (y1 - y0) / 1e6


class Plan:
    def __init__(self, kind, params, width, height, rng):
        self.kind = kind
        self.p = params
        self.width = width
        self.height = height
        self.rng = rng
        self.rooms = []
        self.door_requests = []  # (room index, target: "C" = any corridor or a room index,
        #                            widths [m], style)
        self.start = None
        self.summary = ""

    def add(self, kind, rect, corridor=False):
        x0, y0, x1, y1 = rect
        if not (x1 > x0 and y1 > y0):
            raise GenerationError("empty room %s %s" % (kind, rect))
        self.rooms.append(Room(kind, rect, corridor))
        return len(self.rooms) - 1

    # --- rows of rooms

    def fill_row(self, rect, front, corners=None):
        """Fills rect with rooms along its length; `front` is the side its corridor is on
        (S, N, W, E). corners = (first_cut, last_cut) [mm along the row]: a single room from
        the row's start to first_cut and one from last_cut to its end (the columns along the
        west and east walls, whose ends reach past the corridors)."""
        x0, y0, x1, y1 = rect
        along_x = front in ("S", "N")
        length = (x1 - x0) if along_x else (y1 - y0)
        depth = (y1 - y0) if along_x else (x1 - x0)

        def to_global(u0, u1, v0, v1):
            if front == "S":
                return (x0 + u0, y0 + v0, x0 + u1, y0 + v1)
            if front == "N":
                return (x0 + u0, y1 - v1, x0 + u1, y1 - v0)
            if front == "W":
                return (x0 + v0, y0 + u0, x0 + v1, y0 + u1)
            return (x1 - v1, y0 + u0, x1 - v0, y0 + u1)

        start, end = 0, length
        if corners:
            first, last = corners
            corner_kind = "office" if self.kind == "office" else "bedroom"
            for (u0, u1) in ((0, first), (last, length)):
                area = (u1 - u0) * depth / 1e6
                kind, doors, style = corner_kind, [0.9], "corner"
                if self.kind == "house" and area > 28.0:
                    kind, doors, style = "living_room", [1.6], "center"
                elif self.kind == "office" and area > 40.0:
                    kind, doors = "meeting_room", [1.6]
                i = self.add(kind, to_global(u0, u1, 0, depth))
                self.door_requests.append((i, "C", doors, style))
            start, end = first, last
        self.fill_units(start, end, depth, to_global)

    def fill_units(self, start, end, depth, to_global):
        length_m = (end - start) / 1000.0
        depth_m = depth / 1000.0
        maker = UNIT_MAKERS[self.kind]
        min_unit = MIN_UNIT_M[self.kind]
        units, remaining = [], length_m
        while remaining >= min_unit:
            unit = maker(self.rng, depth_m, remaining)
            if unit is None:
                break
            units.append(unit)
            remaining -= unit.width
        if not units:  # a stretch narrower than any unit: one small room
            units.append(Unit([length_m], single("storage", [0.8])))
        columns = [c for u in units for c in u.columns]
        widths = quantize(columns, end - start)
        u = start
        k = 0
        for unit in units:
            cols = widths[k:k + len(unit.columns)]
            k += len(unit.columns)
            rooms, doors = unit.build(cols, depth)
            first = len(self.rooms)
            for (kind, u0, u1, v0, v1) in rooms:
                self.add(kind, to_global(u + u0, u + u1, v0, v1))
            for (room, target, widths_m, style) in doors:
                self.door_requests.append(
                    (first + room, target if target == "C" else first + target, widths_m, style))
            u += sum(cols)

    def fill_block(self, x0, y0, x1, y1, split_y):
        """A double row between two east-west corridors: the southern row opens south, the
        northern one north. Offices may put a full-depth open-plan area or training room in."""
        segments = [(x0, x1)]
        depth_m = (y1 - y0) / 1000.0
        length_m = (x1 - x0) / 1000.0
        big = None
        if self.kind == "office" and self.rng.random() < 0.5 and 150.0 / depth_m >= 8.0:
            kind = "open_plan" if self.rng.random() < 0.7 else "training_room"
            w = snap(self.rng.uniform(8.0, min(14.0, 150.0 / depth_m)))
            free = (x1 - x0) - w
            if -1000 <= free <= 1000 and length_m >= 8.0:  # the whole block
                big = (x0, x1, kind)
            elif free >= 6000:  # at the west end, the east end, or between two stretches
                choices = [0, free]
                if free >= 12000:
                    choices.append(snap(self.rng.uniform(6.0, free / 1000.0 - 6.0)))
                offset = self.rng.choice(choices)
                big = (x0 + offset, x0 + offset + w, kind)
        if big:
            bx0, bx1, kind = big
            segments = [s for s in ((x0, bx0), (bx1, x1)) if s[1] - s[0] > 0]
            i = self.add(kind, (bx0, y0, bx1, y1))
            if kind == "open_plan":
                self.door_requests.append((i, "C", [self.rng.choice([1.5, 1.8, 2.0]),
                                                    self.rng.choice([1.5, 1.8, 2.0])], "center"))
            else:
                self.door_requests.append((i, "C", [1.8], "center"))
        for (a, b) in segments:
            self.fill_row((a, y0, b, split_y), "S")
            self.fill_row((a, split_y, b, y1), "N")

    # --- the whole floor

    def build(self):
        p, rng = self.p, self.rng
        W, H = self.width, self.height
        cname = p["corridor_name"]

        def sample(rng_range):
            return rng.uniform(*rng_range)

        corr_mid = sum(p["corridor"]) / 2
        perim_mid = sum(p["perimeter"]) / 2
        row_mid = sum(p["row"]) / 2
        span_mid = sum(p["span"]) / 2
        H_m, W_m = H / 1000.0, W / 1000.0
        # East-west corridors: H = 2 perimeter + k corridor + (k - 1) double rows.
        k = max(1, int(round((H_m - 2 * perim_mid + 2 * row_mid) / (corr_mid + 2 * row_mid))))
        ring_min_w = 2 * p["perimeter"][1] + 2 * p["corridor"][1] + 8.0
        if k >= 2 and W_m < ring_min_w:
            k = 1
        if k == 1:
            self.build_single_corridor(cname)
            return
        corridors = [snap(sample(p["corridor"])) for _ in range(k)]
        flex = [sample(p["perimeter"])]
        for _ in range(k - 1):
            flex += [sample(p["row"]), sample(p["row"])]
        flex.append(sample(p["perimeter"]))
        flex_mm = quantize(flex, H - sum(corridors))
        # y of each band
        ys, y = [], 0
        bands = [flex_mm[0]]
        for j in range(k):
            bands.append(corridors[j])
            if j < k - 1:
                bands += [flex_mm[1 + 2 * j], flex_mm[2 + 2 * j]]
        bands.append(flex_mm[-1])
        for b in bands:
            ys.append(y)
            y += b
        ys.append(y)
        # bands: perim, c0, r, r, c1, r, r, ..., c_{k-1}, perim
        corr_y = [(ys[1 + 3 * j], ys[2 + 3 * j]) for j in range(k)]
        # North-south corridors: W = 2 perimeter + m corridor + (m - 1) spans.
        pw, pe = snap(sample(p["perimeter"])), snap(sample(p["perimeter"]))
        m = max(2, int(round((W_m - 2 * perim_mid + span_mid) / (corr_mid + span_mid))))
        while m > 2 and (W_m - 2 * perim_mid - m * corr_mid) / (m - 1) < 10.0:
            m -= 1
        vcorr = [snap(sample(p["corridor"])) for _ in range(m)]
        spans = quantize([rng.uniform(0.85, 1.15) for _ in range(m - 1)],
                         W - pw - pe - sum(vcorr))
        if min(spans) < 6000:
            raise GenerationError("building too narrow for its corridors")
        corr_x, x = [], pw
        for i in range(m):
            corr_x.append((x, x + vcorr[i]))
            x += vcorr[i] + (spans[i] if i < m - 1 else 0)
        assert x == W - pe, (x, W - pe)

        # corridors: east-west segments between the north-south corridors (each with the
        # junction at its west end; the last with both), north-south segments between them
        for j, (cy0, cy1) in enumerate(corr_y):
            for i in range(m - 1):
                xa = corr_x[i][0]
                xb = corr_x[i + 1][0] if i < m - 2 else corr_x[m - 1][1]
                idx = self.add(cname, (xa, cy0, xb, cy1), corridor=True)
                self.rooms[idx].name = "%s_ew%d_%d" % (cname, j + 1, i + 1)
        for i, (cx0, cx1) in enumerate(corr_x):
            for j in range(k - 1):
                idx = self.add(cname, (cx0, corr_y[j][1], cx1, corr_y[j + 1][0]), corridor=True)
                self.rooms[idx].name = "%s_ns%d_%d" % (cname, i + 1, j + 1)
        # start: the middle of the southern corridor, in the span nearest the centre
        i_mid = min(range(m - 1), key=lambda i: abs((corr_x[i][1] + corr_x[i + 1][0]) / 2 - W / 2))
        sx = (corr_x[i_mid][1] + corr_x[i_mid + 1][0]) // 2 // DOOR_SNAP * DOOR_SNAP
        sy = (corr_y[0][0] + corr_y[0][1]) // 2 // DOOR_SNAP * DOOR_SNAP
        self.start = (sx, sy, 0)

        # rows along the outer walls
        self.fill_row((pw, 0, W - pe, corr_y[0][0]), "N")
        self.fill_row((pw, corr_y[-1][1], W - pe, H), "S")
        for (rect, front) in (((0, 0, pw, H), "E"), ((W - pe, 0, W, H), "W")):
            first = corr_y[0][0] + snap(rng.uniform(2.2, 3.0))
            last = corr_y[-1][1] - snap(rng.uniform(2.2, 3.0))
            self.fill_row(rect, front, corners=(first, last))
        # double rows between the east-west corridors
        for j in range(k - 1):
            y0, y1 = corr_y[j][1], corr_y[j + 1][0]
            split = ys[3 + 3 * j]
            for i in range(m - 1):
                self.fill_block(corr_x[i][1], y0, corr_x[i + 1][0], y1, split)
        self.summary = ("%d east-west and %d north-south %ss (%s-%s m wide) forming a ring "
                        "and a grid" % (k, m, cname, fmt(min(corridors + vcorr)),
                                        fmt(max(corridors + vcorr))))

    def build_single_corridor(self, cname):
        """Small buildings: one corridor from the west wall to the east wall, rooms both sides."""
        p, rng, W = self.p, self.rng, self.width
        ps, pn = snap(rng.uniform(*p["perimeter"])), snap(rng.uniform(*p["perimeter"]))
        c = snap(rng.uniform(*p["corridor"]))
        H = ps + c + pn
        W = snap(self.width / 1000.0 * self.height / H)  # same gross area, one corridor deep
        self.width, self.height = W, H
        idx = self.add(cname, (0, ps, W, ps + c), corridor=True)
        self.rooms[idx].name = cname
        self.start = (W // 2 // DOOR_SNAP * DOOR_SNAP, (ps + c // 2) // DOOR_SNAP * DOOR_SNAP, 0)
        self.fill_row((0, 0, W, ps), "N")
        self.fill_row((0, ps + c, W, H), "S")
        self.summary = "one %s (%s m wide) from wall to wall" % (cname, fmt(c))


# --------------------------------------------------------------------------------------------
# Geometry: walls from the room tiling, doors on shared edges, the free floor area.


def check_tiling(plan):
    """Rooms must cover the building exactly once (checked on the 0.1 m lattice)."""
    nx, ny = plan.width // GRID, plan.height // GRID
    rows = [bytearray(nx) for _ in range(ny)]
    for r in plan.rooms:
        x0, y0, x1, y1 = (v // GRID for v in r.rect)
        if x0 < 0 or y0 < 0 or x1 > nx or y1 > ny:
            raise GenerationError("room %s %s outside the building" % (r.kind, r.rect))
        for yy in range(y0, y1):
            seg = rows[yy][x0:x1]
            if seg.count(0) != len(seg):
                raise GenerationError("rooms overlap at %s" % (r.rect,))
            rows[yy][x0:x1] = b"\x01" * (x1 - x0)
    for yy, row in enumerate(rows):
        if row.count(0):
            raise GenerationError("floor not covered by rooms at y=%s" % fmt(yy * GRID))


def elementary_edges(plan):
    """Pieces of room boundaries with the room on each side: (orient, c, a, b, r1, r2);
    orient 'h' = the line y = c (r1 above, r2 below), 'v' = x = c (r1 east, r2 west);
    None = outside."""
    lines = {"h": defaultdict(lambda: ([], [])), "v": defaultdict(lambda: ([], []))}
    for i, r in enumerate(plan.rooms):
        x0, y0, x1, y1 = r.rect
        lines["h"][y0][0].append((x0, x1, i))
        lines["h"][y1][1].append((x0, x1, i))
        lines["v"][x0][0].append((y0, y1, i))
        lines["v"][x1][1].append((y0, y1, i))
    edges = []
    for orient in ("h", "v"):
        for c, (side1, side2) in lines[orient].items():
            side1.sort()
            side2.sort()
            starts1 = [s[0] for s in side1]
            starts2 = [s[0] for s in side2]
            pts = sorted({v for s in side1 + side2 for v in s[:2]})

            def cover(side, starts, a, b):
                k = bisect.bisect_right(starts, a) - 1
                if k >= 0 and side[k][0] <= a and side[k][1] >= b:
                    return side[k][2]
                return None

            for a, b in zip(pts, pts[1:]):
                r1 = cover(side1, starts1, a, b)
                r2 = cover(side2, starts2, a, b)
                if r1 is None and r2 is None:
                    continue
                edges.append((orient, c, a, b, r1, r2))
    return edges


def wall_thickness(plan, r1, r2):
    if r1 is None or r2 is None:
        return OUTER_WALL
    c1, c2 = plan.rooms[r1].corridor, plan.rooms[r2].corridor
    if c1 and c2:
        return 0
    return CORRIDOR_WALL if (c1 or c2) else PARTITION


def make_walls(plan, edges):
    """Merged wall segments (orient, c, a, b, thickness), each end run past the crossing
    walls by half the thickest one's thickness so corners are solid."""
    by_line = defaultdict(list)
    for (orient, c, a, b, r1, r2) in edges:
        t = wall_thickness(plan, r1, r2)
        if t:
            by_line[(orient, c)].append((a, b, t))
    segments = []
    for (orient, c), pieces in by_line.items():
        pieces.sort()
        cur = None
        for (a, b, t) in pieces:
            if cur and cur[1] == a and cur[2] == t:
                cur[1] = b
            else:
                if cur:
                    segments.append((orient, c, cur[0], cur[1], cur[2]))
                cur = [a, b, t]
        segments.append((orient, c, cur[0], cur[1], cur[2]))
    index = {"h": defaultdict(list), "v": defaultdict(list)}
    for (orient, c, a, b, t) in segments:
        index[orient][c].append((a, b, t))

    def crossing(orient, line_c, at):
        other = "v" if orient == "h" else "h"
        return max([t for (a, b, t) in index[other].get(at, []) if a <= line_c <= b], default=0)

    walls = []
    for (orient, c, a, b, t) in segments:
        walls.append((orient, c, a - crossing(orient, c, a) // 2,
                      b + crossing(orient, c, b) // 2, t))
    return walls


def place_doors(plan, edges):
    """Turns door requests into doors (x, y, width [mm], room, other room, orient) on the runs of
    boundary a room shares with its target."""
    rng = plan.rng
    per_room = defaultdict(list)
    for (orient, c, a, b, r1, r2) in edges:
        if r1 is not None and r2 is not None:
            per_room[r1].append((orient, c, a, b, r2))
            per_room[r2].append((orient, c, a, b, r1))
    doors = []
    for (room, target, widths_m, style) in plan.door_requests:
        def matches(other):
            return plan.rooms[other].corridor if target == "C" else other == target
        pieces = sorted((o, c, a, b, other) for (o, c, a, b, other) in per_room[room]
                        if matches(other))
        runs = []
        for (o, c, a, b, other) in pieces:
            if runs and runs[-1][0] == o and runs[-1][1] == c and runs[-1][3] == a:
                runs[-1][3] = b
                runs[-1][4].add(other)
            else:
                runs.append([o, c, a, b, {other}])
        widths = [snap(w) for w in widths_m]
        need = max(widths) + 2 * DOOR_MARGIN
        runs = [r for r in runs if r[3] - r[2] >= need]
        if not runs:
            raise GenerationError("no place for the door of %s %s" % (
                plan.rooms[room].kind, plan.rooms[room].rect))
        runs.sort(key=lambda r: (-(r[3] - r[2]), r[0], r[1], r[2]))
        slots = []
        if len(runs) >= len(widths):
            slots = [tuple(r[:4]) for r in runs[:len(widths)]]
        else:  # split the longest run among the doors
            o, c, a, b = runs[0][:4]
            n = len(widths)
            step = (b - a) // n
            slots = [(o, c, a + i * step, a + (i + 1) * step if i < n - 1 else b) for i in range(n)]
        for (o, c, a, b), w in zip(slots, widths):
            lo = a + DOOR_MARGIN + w // 2
            hi = b - DOOR_MARGIN - w // 2
            lo = -(-lo // DOOR_SNAP) * DOOR_SNAP
            hi = hi // DOOR_SNAP * DOOR_SNAP
            if hi < lo:
                raise GenerationError("door of %s does not fit" % plan.rooms[room].kind)
            if style == "center":
                frac = rng.uniform(0.3, 0.7)
            else:
                frac = rng.choice([rng.uniform(0.0, 0.15), rng.uniform(0.85, 1.0), rng.random()])
            pos = lo + int(round((hi - lo) * frac / DOOR_SNAP)) * DOOR_SNAP
            pos = min(max(pos, lo), hi)
            x, y = (pos, c) if o == "h" else (c, pos)
            other = next(iter(runs[0][4])) if target == "C" else target
            for r in runs:
                if r[0] == o and r[1] == c and r[2] <= pos <= r[3]:
                    other = min(r[4])
            doors.append((x, y, w, room, other, o))
    return doors


def cut_doors(walls, doors):
    """Wall pieces left after the doorways are cut, as roomscout cuts them (a door cuts every
    wall whose centre line passes within half its thickness of the door's centre); checks
    that each door cuts only the wall it stands in, and all of its width."""
    index = {"h": defaultdict(list), "v": defaultdict(list)}
    for w in walls:
        index[w[0]][w[1]].append(w)
    gaps = defaultdict(list)
    for (x, y, width, _room, _other, own) in doors:
        line, along = (y, x) if own == "h" else (x, y)
        touched = []
        for orient, o_line, o_along in (("h", y, x), ("v", x, y)):
            for c in range(o_line - OUTER_WALL, o_line + OUTER_WALL + 1, DOOR_SNAP):
                for w in index[orient].get(c, []):
                    _, wc, a, b, t = w
                    closest = min(max(o_along, a), b)
                    if math.hypot(o_along - closest, o_line - wc) <= t / 2.0 + 1e-3:
                        touched.append(w)
        if not touched:
            raise GenerationError("door at %s, %s touches no wall" % (fmt(x), fmt(y)))
        for w in touched:
            _, wc, a, b, t = w
            if w[0] != own or wc != line or not (a < along - width // 2 < along + width // 2 < b):
                raise GenerationError("door at %s, %s would cut a crossing wall or run past "
                                      "the end of its wall" % (fmt(x), fmt(y)))
            gaps[w].append((along - width // 2, along + width // 2))
    pieces = []
    for w in walls:
        orient, c, a, b, t = w
        at = a
        for (g0, g1) in sorted(gaps.get(w, [])):
            if g0 > at:
                pieces.append((orient, c, at, g0, t))
            at = max(at, g1)
        if b > at:
            pieces.append((orient, c, at, b, t))
    return pieces


def free_area_m2(plan, pieces):
    """Building area inside the outer walls' centre lines minus the union of the walls."""
    W, H = plan.width, plan.height
    rects = []
    for (orient, c, a, b, t) in pieces:
        if orient == "h":
            x0, x1, y0, y1 = a, b, c - t // 2, c + t // 2
        else:
            x0, x1, y0, y1 = c - t // 2, c + t // 2, a, b
        x0, y0, x1, y1 = max(x0, 0), max(y0, 0), min(x1, W), min(y1, H)
        if x1 > x0 and y1 > y0:
            rects.append((x0, y0, x1, y1))
    events = defaultdict(list)
    for k, (x0, y0, x1, y1) in enumerate(rects):
        events[x0].append((k, True))
        events[x1].append((k, False))
    xs = sorted(events)
    active = {}
    covered = 0
    for xa, xb in zip(xs, xs[1:]):
        for (k, add) in events[xa]:
            if add:
                active[k] = (rects[k][1], rects[k][3])
            else:
                active.pop(k, None)
        length, end = 0, None
        for (y0, y1) in sorted(active.values()):
            if end is None or y0 > end:
                length += y1 - y0
                end = y1
            elif y1 > end:
                length += y1 - end
                end = y1
        covered += length * (xb - xa)
    return (W * H - covered) / 1e6


def check_connected(plan, doors, edges):
    """Every room reachable from the start's room through doors and open corridor joins."""
    graph = defaultdict(set)
    for (_x, _y, _w, a, b, _o) in doors:
        graph[a].add(b)
        graph[b].add(a)
    for (_o, _c, _a, _b, r1, r2) in edges:
        if r1 is not None and r2 is not None and wall_thickness(plan, r1, r2) == 0:
            graph[r1].add(r2)
            graph[r2].add(r1)
    sx, sy, _ = plan.start
    start = next(i for i, r in enumerate(plan.rooms)
                 if r.corridor and r.rect[0] < sx < r.rect[2] and r.rect[1] < sy < r.rect[3])
    seen, todo = {start}, [start]
    while todo:
        for n in graph[todo.pop()]:
            if n not in seen:
                seen.add(n)
                todo.append(n)
    if len(seen) != len(plan.rooms):
        lost = [plan.rooms[i].kind for i in range(len(plan.rooms)) if i not in seen]
        raise GenerationError("%d rooms unreachable (%s ...)" % (len(lost), ", ".join(lost[:5])))


def bad_door_widths(doors):
    return [d for d in doors if not (800 <= d[2] <= 2000)]


# --------------------------------------------------------------------------------------------


class World:
    def __init__(self, plan, walls, doors, free_m2):
        self.plan, self.walls, self.doors, self.free_m2 = plan, walls, doors, free_m2


def generate_once(kind, width, height, seed):
    params = KINDS[kind]
    plan = Plan(kind, params, width, height, random.Random(seed))
    plan.build()
    check_tiling(plan)
    edges = elementary_edges(plan)
    walls = make_walls(plan, edges)
    doors = place_doors(plan, edges)
    if bad_door_widths(doors):
        raise GenerationError("door width outside 0.8-2 m")
    pieces = cut_doors(walls, doors)
    check_connected(plan, doors, edges)
    name_rooms(plan)
    return World(plan, walls, doors, free_area_m2(plan, pieces))


def name_rooms(plan):
    counts = defaultdict(int)
    for r in plan.rooms:
        if r.name:
            continue
        counts[r.kind] += 1
        r.name = "%s_%d" % (r.kind, counts[r.kind])


def dimensions(gross_m2, aspect, side_max):
    width = snap(math.sqrt(gross_m2 * aspect))
    height = snap(gross_m2 / (width / 1000.0))
    if raster_cells(width, height) > MAX_GRID_CELLS:
        width = min(width, side_max)
        height = snap(gross_m2 / (width / 1000.0))
        if raster_cells(width, height) > MAX_GRID_CELLS:
            width = height = side_max
    return width, height


def generate(kind, area_m2, seed):
    params = KINDS[kind]
    aspect = random.Random(seed).uniform(1.0, 1.35)
    side_max = largest_side_mm()
    gross = area_m2 / params["free_fraction"]
    best = None
    for attempt in range(10):
        width, height = dimensions(gross, aspect, side_max)
        world = generate_once(kind, width, height, seed)
        error = abs(world.free_m2 - area_m2) / area_m2
        if best is None or error < best[0]:
            best = (error, world)
        if error <= AREA_GOAL:
            break
        gross *= area_m2 / world.free_m2
    error, world = best
    if error > AREA_TOLERANCE:
        raise GenerationError("could not reach %g m2 of free floor (best %.1f m2)" %
                              (area_m2, world.free_m2))
    plan = world.plan
    if raster_cells(plan.width, plan.height) > MAX_GRID_CELLS:
        raise GenerationError("the building's raster exceeds kMaxGridCells")
    return world


# --------------------------------------------------------------------------------------------


def describe_rooms(plan):
    counts = defaultdict(int)
    for r in plan.rooms:
        counts[r.kind] += 1
    cname = plan.p["corridor_name"]
    order = [cname] + sorted((k for k in counts if k != cname), key=lambda k: (-counts[k], k))
    parts = []
    plural = {"storage": "storage rooms", "open_plan": "open-plan areas", "wc": "WCs",
              "walk_in_closet": "walk-in closets", "laundry": "laundry rooms",
              "study": "studies", cname: cname + " segments"}
    for k in order:
        label = plural.get(k, k.replace("_", " ") + "s") if counts[k] > 1 else \
            ("WC" if k == "wc" else k.replace("_", " ") + (" segment" if k == cname else ""))
        parts.append("%d %s" % (counts[k], label))
    return ", ".join(parts)


def write_world(path, world, name, kind, command):
    plan = world.plan
    W, H = plan.width, plan.height
    n_rooms = len(plan.rooms)
    lines = []
    room_text = describe_rooms(plan)
    header = [
        "Generated %s (%s), %s m x %s m: %s." % (plan.p["title"], kind, fmt(W), fmt(H),
                                                 plan.summary),
        "Made by: %s" % command,
        "Free floor area (inside the outer walls, minus walls, doorways open): %.1f m2, "
        "computed exactly from the wall rectangles (their edges lie on roomscout's 0.025 m "
        "raster)." % world.free_m2,
        "%d rooms: %s." % (n_rooms, room_text),
        "Outer walls 0.2 m (centre lines x 0/%s, y 0/%s; segments run 0.1 m past the corners), "
        "%s walls 0.15 m, partitions 0.1 m. Doors %s-%s m, openings up to %s m. Start: middle "
        "of the southern %s." % (fmt(W), fmt(H), plan.p["corridor_name"],
                                 fmt(min(d[2] for d in world.doors if d[2] <= 1000)),
                                 fmt(max(d[2] for d in world.doors if d[2] <= 1000)),
                                 fmt(max(d[2] for d in world.doors)), plan.p["corridor_name"]),
    ]
    for h in header:
        lines += ["# " + line for line in ([h] if h.startswith("Made by") else wrap(h, 92))]
    lines.append("name: %s" % name)
    lines.append('description: "Generated %s, %d m2, %d rooms"' % (kind, round(world.free_m2),
                                                                  n_rooms))
    lines.append("wall_thickness_m: %s" % fmt(PARTITION))
    lines.append("wall_height_m: %s" % plan.p["wall_height"])
    sx, sy, yaw = plan.start
    lines.append("start: [%s, %s, %d]" % (fmt(sx), fmt(sy), yaw))
    lines.append("")
    lines.append("walls:")
    groups = [(OUTER_WALL, "outer walls (0.2 m)"),
              (CORRIDOR_WALL, "%s walls (0.15 m)" % plan.p["corridor_name"]),
              (PARTITION, "partitions (0.1 m)")]
    for t, title in groups:
        lines.append("  # --- " + title)
        for (orient, c, a, b, wt) in sorted(w for w in world.walls if w[4] == t):
            pts = ([[a, c], [b, c]] if orient == "h" else [[c, a], [c, b]])
            text = "[[%s, %s], [%s, %s]]" % (fmt(pts[0][0]), fmt(pts[0][1]),
                                             fmt(pts[1][0]), fmt(pts[1][1]))
            if t == PARTITION:
                lines.append("  - " + text)
            else:
                lines.append("  - {points: %s, thickness_m: %s}" % (text, fmt(t)))
    lines.append("")
    lines.append("doors:")
    for (x, y, w, room, other, _o) in world.doors:
        lines.append("  - {center: [%s, %s], width_m: %s}  # %s <-> %s" % (
            fmt(x), fmt(y), fmt(w), plan.rooms[room].name, plan.rooms[other].name))
    lines.append("")
    lines.append("rooms:")
    order = sorted(range(n_rooms), key=lambda i: (not plan.rooms[i].corridor, i))
    for i in order:
        r = plan.rooms[i]
        x0, y0, x1, y1 = (fmt(v) for v in r.rect)
        lines.append("  - {name: %s, polygon: [[%s, %s], [%s, %s], [%s, %s], [%s, %s]]}" % (
            r.name, x0, y0, x1, y0, x1, y1, x0, y1))
    text = "\n".join(lines) + "\n"
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def wrap(text, width):
    out, line = [], ""
    for word in text.split(" "):
        if line and len(line) + 1 + len(word) > width:
            out.append(line)
            line = word
        else:
            line = word if not line else line + " " + word
    out.append(line)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("yaml", metavar="OUT.yaml", help="world file to write")
    parser.add_argument("--kind", choices=sorted(KINDS), required=True)
    parser.add_argument("--area-m2", type=float, required=True,
                        help="free floor area to aim for [m2] (the result is within 10 %%)")
    parser.add_argument("--seed", type=int, default=1, help="seed of every random choice")
    parser.add_argument("--name", help="world name, [a-z0-9_]+ (default: OUT's file stem)")
    args = parser.parse_args()

    area = args.area_m2
    params = KINDS[args.kind]
    if not math.isfinite(area) or area < MIN_AREA_M2:
        parser.error("--area-m2 must be at least %g m2 (got %s): a smaller building has no "
                     "room for a corridor with rooms on both sides" % (MIN_AREA_M2, args.area_m2))
    if area > params["max_area"]:
        side = largest_side_mm() / 1000.0
        parser.error(
            "--area-m2 %g is too large for --kind %s: at most %d m2. roomscout rasterises a "
            "world at 0.025 m (world.raster_resolution_m) and refuses grids of more than "
            "kMaxGridCells = 25 000 000 cells (src/roomscout/core/grid_limits.hpp), so a "
            "building can be at most about %.1f m x %.1f m" %
            (area, args.kind, params["max_area"], side, side))
    name = args.name
    if name is None:
        name = re.sub(r"[^a-z0-9_]", "_", os.path.splitext(os.path.basename(args.yaml))[0].lower())
    if not re.fullmatch(r"[a-z0-9_]+", name):
        parser.error("--name %r must match [a-z0-9_]+" % name)
    out_dir = os.path.dirname(os.path.abspath(args.yaml))
    if not os.path.isdir(out_dir):
        parser.error("the directory of OUT.yaml does not exist: %s" % out_dir)

    try:
        world = generate(args.kind, area, args.seed)
    except GenerationError as e:
        sys.exit("make_building.py: error: %s" % e)
    command = " ".join(["scripts/make_building.py"] + [shlex.quote(a) for a in sys.argv[1:]])
    write_world(args.yaml, world, name, args.kind, command)
    print("%s: %s m x %s m, %.1f m2 free floor, %d rooms, %d doors" % (
        args.yaml, fmt(world.plan.width), fmt(world.plan.height), world.free_m2,
        len(world.plan.rooms), len(world.doors)))


if __name__ == "__main__":
    main()
