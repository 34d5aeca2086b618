#!/usr/bin/python3
"""Reads linkwright-cli's DXF drawings back with ezdxf (Debian: python3-ezdxf), a reader
independent of the dxflib that wrote them, for a four-bar, a slider-crank, a quick return and
two six-bars. For each: ezdxf's auditor finds no error; the layers are GROUND and the links;
$INSUNITS is 4 (mm); every CIRCLE on a moving layer is centred, to 1e-9 mm, on a point whose
position `linkwright-cli analyze` prints at the same crank angle, and every moving point has
one (a hole on a link at a ground pivot is at one of GROUND's circles, which are the pivots
the example defines); every outline is a closed LWPOLYLINE that, with its bulges as ezdxf reads them, encloses
exactly the offset of its holes' convex hull (Steiner's formula). Then bad options: exit 2, the option named, and no file written.

Usage: dxf_readback.py LINKWRIGHT_CLI SCRATCH_DIR
"""
import csv
import io
import math
import os
import subprocess
import sys

try:
    import ezdxf
    import ezdxf.math
except ImportError:
    sys.exit("dxf_readback: ezdxf is missing: install python3-ezdxf (packaging/install-deps.sh)")

TOLERANCE = 1e-9  # the bound, in the drawing's unit (mm here)

# example, crank angle (deg), the layers expected, the ground pivots (mm) from its definition
CASES = [
    ("thesis-crank-rocker", 30.0, ["GROUND", "crank", "coupler", "rocker"], [(0.0, 0.0), (60.0, 0.0)]),
    ("ls3-engine", 123.0, ["GROUND", "crank", "rod", "slider_C"], [(0.0, 0.0)]),
    ("shaper", 200.0, None, None),
    ("watt-i", 45.0, None, None),
    ("stephenson-ii", 10.0, None, None),
]


def run(cli, *args):
    return subprocess.run([cli, *args], capture_output=True, text=True, check=False)


def moving_points(cli, example, angle):
    """Point name -> (x, y) from analyze's CSV at one crank angle."""
    result = run(cli, "analyze", "--example", example, "--from", repr(angle), "--to", repr(angle),
                 "--samples", "1")
    assert result.returncode == 0, result.stderr
    rows = list(csv.DictReader(io.StringIO(result.stdout)))
    assert len(rows) == 1, result.stdout
    points = {}
    for column, text in rows[0].items():
        if column.endswith("_x_mm"):
            name = column[: -len("_x_mm")]
            points[name] = (float(text), float(rows[0][name + "_y_mm"]))
    return points


def near(a, b):
    return abs(a[0] - b[0]) <= TOLERANCE and abs(a[1] - b[1]) <= TOLERANCE


def hull(points):
    """Convex hull, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out

    return half(pts)[:-1] + half(reversed(pts))[:-1]


def area(polygon):
    return 0.5 * sum(a[0] * b[1] - a[1] * b[0] for a, b in zip(polygon, polygon[1:] + polygon[:1]))


def perimeter(polygon):
    if len(polygon) < 2:
        return 0.0
    return sum(math.dist(a, b) for a, b in zip(polygon, polygon[1:] + polygon[:1]))


def boundary(outline, per_arc=4000):
    """The outline as a polygon: its vertices and, along each bulged edge, points on the arc
    ezdxf's bulge_to_arc makes of it (DXF's convention, read by ezdxf, not by us)."""
    vertices = outline.get_points("xyb")
    polygon = []
    for (x, y, bulge), (qx, qy, _) in zip(vertices, vertices[1:] + vertices[:1]):
        if bulge == 0.0:
            polygon.append((x, y))
            continue
        centre, start, end, radius = ezdxf.math.bulge_to_arc((x, y), (qx, qy), bulge)
        sweep = (end - start) % (2.0 * math.pi)
        arc = [(centre.x + radius * math.cos(start + sweep * k / per_arc),
                centre.y + radius * math.sin(start + sweep * k / per_arc)) for k in range(per_arc + 1)]
        if math.dist(arc[0], (x, y)) > math.dist(arc[-1], (x, y)):
            arc.reverse()  # ezdxf gives arcs counter-clockwise; this edge runs clockwise
        polygon.extend(arc[:-1])
    return polygon


def check_outlines(example, name, outlines, circles, failures):
    """The part's outline, with its bulges as ezdxf reads them, encloses the area Steiner's
    formula gives for circles of radius r round the hull H of its holes and slot ends:
    A(H) + r P(H) + π r². A bulge of the wrong sign or size changes it. A slot (arcs as wide
    as a hole) is checked the same way round its two ends."""
    if not outlines or not circles:
        return
    hole_r = circles[0].dxf.radius
    centres = [(c.dxf.center.x, c.dxf.center.y) for c in circles]
    for index, outline in enumerate(outlines):
        arcs = [e for e in outline.virtual_entities() if e.dxftype() == "ARC"]
        if not arcs:
            continue  # a slider block: a rectangle
        r = arcs[0].dxf.radius
        ends = [(a.dxf.center.x, a.dxf.center.y) for a in arcs]
        # The first outline goes round the holes (and any slot's ends); a slot round its ends.
        h = hull(ends if index > 0 else centres + ends)
        expected = area(h) + r * perimeter(h) + math.pi * r * r
        drawn = abs(area(boundary(outline)))
        if abs(drawn - expected) > 1e-6 * expected:
            failures.append(f"{example}: outline {index} on {name} encloses {drawn}, Steiner gives {expected}")
        if index == 0 and r <= hole_r:
            failures.append(f"{example}: the plate on {name} is no wider than its holes")


def check_case(cli, scratch, case, failures):
    example, angle, layers, ground = case
    path = os.path.join(scratch, example + ".dxf")
    result = run(cli, "dxf", "--example", example, "--at", repr(angle), "-o", path)
    if result.returncode != 0:
        failures.append(f"{example}: dxf exited {result.returncode}: {result.stderr}")
        return
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    if auditor.has_errors:
        failures.append(f"{example}: ezdxf audit: {[str(e.message) for e in auditor.errors]}")
    if doc.header.get("$INSUNITS") != 4:
        failures.append(f"{example}: $INSUNITS {doc.header.get('$INSUNITS')}, expected 4 (mm)")
    # ezdxf adds its own Defpoints layer on reading; "0" is DXF's default layer.
    names = [layer.dxf.name for layer in doc.layers if layer.dxf.name not in ("0", "Defpoints")]
    if layers is not None and sorted(names) != sorted(layers):
        failures.append(f"{example}: layers {names}, expected {layers}")
    if "GROUND" not in names:
        failures.append(f"{example}: no GROUND layer")
    msp = doc.modelspace()
    points = moving_points(cli, example, angle)
    pivots = [(c.dxf.center.x, c.dxf.center.y) for c in msp.query('CIRCLE[layer=="GROUND"]')]
    found = set()
    for name in names:
        circles = msp.query(f'CIRCLE[layer=="{name}"]')
        outlines = msp.query(f'LWPOLYLINE[layer=="{name}"]')
        if name != "GROUND" and (len(outlines) == 0 or not all(p.closed for p in outlines)):
            failures.append(f"{example}: layer {name} has no closed outline")
        if len(circles) == 0:
            failures.append(f"{example}: layer {name} has no hole")
        check_outlines(example, name, outlines, circles, failures)
        for circle in circles:
            centre = (circle.dxf.center.x, circle.dxf.center.y)
            matches = [p for p, xy in points.items() if near(xy, centre)]
            if name == "GROUND":
                # Ground pivots do not move, so analyze lists none: the example defines them.
                if ground is not None and not any(near(g, centre) for g in ground):
                    failures.append(f"{example}: ground hole at {centre} is no pivot of {ground}")
                continue
            # A link's hole at a ground pivot is where it turns on the frame.
            if not matches and not any(near(p, centre) for p in pivots):
                failures.append(f"{example}: hole at {centre} on {name} is on no joint analyze reports")
            found.update(matches)
    if ground is not None and len(pivots) != len(ground):
        failures.append(f"{example}: GROUND has {len(pivots)} holes, expected {len(ground)}")
    missing = set(points) - found
    if missing:
        failures.append(f"{example}: no hole at {sorted(missing)}")


def check_refusals(cli, scratch, failures):
    path = os.path.join(scratch, "refused.dxf")
    cases = [
        (["--hole", "0"], "--hole"),
        (["--hole", "nan"], "--hole"),
        (["--hole", "1000"], "--hole"),
        (["--hole", "2", "--width", "2"], "--width"),
        (["--at", "10", "--at", "20"], "--at"),
    ]
    for extra, option in cases:
        result = run(cli, "dxf", "--example", "thesis-crank-rocker", *extra, "-o", path)
        if result.returncode != 2 or option not in result.stderr:
            failures.append(f"dxf {extra}: exit {result.returncode}, stderr {result.stderr!r}; expected 2 naming {option}")
        if os.path.exists(path):
            failures.append(f"dxf {extra}: wrote {path} although refused")
            os.remove(path)
    # A non-Grashof four-bar has angles where it cannot be assembled: exit 3, nothing written.
    result = run(cli, "dxf", "--fourbar", "60,40,30,20", "--at", "180", "-o", path)
    if result.returncode != 3 or "--at" not in result.stderr or os.path.exists(path):
        failures.append(f"dxf at an unassemblable angle: exit {result.returncode}, {result.stderr!r}")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    cli, scratch = sys.argv[1], sys.argv[2]
    os.makedirs(scratch, exist_ok=True)
    failures = []
    for case in CASES:
        check_case(cli, scratch, case, failures)
    check_refusals(cli, scratch, failures)
    for f in failures:
        print("FAIL", f)
    print(f"dxf_readback: {len(CASES)} drawings, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
