#!/usr/bin/env python3
"""Fidelity benchmark of the colour-aware decimation against its peers (docs/RESULTS.md).

For every mesh (the PLY files of ../shared/data by default, or the paths given) and every
reduction (0.9, 0.97 and 0.99 by default: the paper's 90-97 % and one more point for the plot), each method simplifies the mesh with
`color-decimate-run`, then
  - `color-decimate-metro` measures the two-sided geometric distance (Metro's method: mean,
    RMS and max as % of the original's bounding-box diagonal, the paper's Table 2);
  - `color-decimate-eval` renders both meshes unlit from the six axis views and measures the
    colour RMS (0-255) and PSNR (dB) (the paper's Table 3);
and the runner reports the time, the peak memory and the metric's bytes per vertex (Table 1).

Methods: vtkColorHalfEdgeDecimation at its defaults (AttributeQuadric with boundary planes,
Batched) and with the paper's method (HalfEdgeColor, Greedy), HalfEdgeColor with an earlier
study's BoundaryWeight and GeometryWeight, HalfEdgeColor in CIELab, the
Geometry metric, Garland-Heckbert's ColorQuadric (half-edge, optimal placement, CIELab),
vtkQuadricDecimation with its attribute error metric on and off, meshoptimizer 0.18's
meshopt_simplify (geometry only; Debian's native library), and meshoptimizer 1.3's
simplifyWithAttributes, simplifyWithUpdate and simplifyWithAttributes with the Prune flag (the
colour as 3 attributes; the npm package's WebAssembly build, run by node: its times are
measured inside node; these are left out, with the reason, when node or the package is
missing: npm ci --prefix Tools/MeshOptimizerJS). On meshes whose colour does not vary, the
methods that differ only in how they treat colour are left out.

Writes docs/RESULTS.md (tables in the shape of the paper's Tables 1-3) and
docs/images/psnr_vs_ratio.png (PSNR against compression ratio, as Fig. 1 of Yildiz et al.),
and keeps every run's JSON in the work folder (--resume reuses them).

Run from the repository: python3 Tools/fidelity-benchmark.py --build build
"""

import argparse
import datetime
import functools
import json
import math
import os
import platform
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# id, label, runner arguments, colour-only (left out when the colour does not vary)
METHODS = [
    ("def", "defaults (AttributeQuadric, scene-relative weights, Batched)", ["--method", "defaults"],
     False),
    ("hec", "HalfEdgeColor (the paper's method)", ["--method", "paper"], False),
    # The setting an earlier study recommended for the paper's cost.
    ("hec-bw", "HalfEdgeColor, BoundaryWeight 100, GeometryWeight 10",
     ["--method", "half-edge-color", "--boundary-weight", "100", "--geometry-weight", "10"],
     False),
    ("hec-lab", "HalfEdgeColor, CIELab", ["--method", "half-edge-color", "--cielab"], True),
    ("geo", "Geometry (half-edge QEM)", ["--method", "geometry"], True),
    ("cq", "ColorQuadric, half-edge", ["--method", "color-quadric"], False),
    # Full collapses with Garland-Heckbert's boundary constraints, as QSlim has them: without,
    # open boundaries shrink (see RESULTS.md).
    ("cq-opt", "ColorQuadric, optimal placement, BoundaryWeight 100",
     ["--method", "color-quadric", "--placement", "--boundary-weight", "100"], False),
    ("cq-lab", "ColorQuadric, CIELab", ["--method", "color-quadric", "--cielab"], True),
    # Cleaned first: VTK 9.1's attribute quadrics fail on zero-area triangles ("Unable to
    # factor attribute matrix") and the decimation then stops early (see RESULTS.md).
    ("vtkqd-attr", "vtkQuadricDecimation, attributes on",
     ["--method", "vtk-quadric", "--attributes", "--clean"], True),
    ("vtkqd", "vtkQuadricDecimation, attributes off", ["--method", "vtk-quadric"], False),
    ("meshopt", "meshoptimizer 0.18 meshopt_simplify", ["--method", "meshopt"], False),
    # meshoptimizer's current attribute modes, the colour as 3 attributes of weight 1
    # (WebAssembly: the times are node's).
    ("meshopt-attr", "meshoptimizer 1.3 simplifyWithAttributes (WebAssembly)",
     ["--method", "meshopt-attr"], True),
    ("meshopt-update", "meshoptimizer 1.3 simplifyWithUpdate (WebAssembly)",
     ["--method", "meshopt-update"], True),
    ("meshopt-prune", "meshoptimizer 1.3 simplifyWithAttributes + Prune (WebAssembly)",
     ["--method", "meshopt-prune"], True),
]
# color-decimate-run's exit status when a method's peer (node, the npm package) is missing.
MISSING_PEER = 4
METHOD_LABEL = {m[0]: m[1] for m in METHODS}
ANALYSIS_BEGIN = "<!-- analysis: kept when the script rewrites this file -->"
ANALYSIS_END = "<!-- end of analysis -->"


PEERS = ("meshopt-attr", "meshopt-update", "vtkqd-attr")


def aims(w, by, meshes, coloured, reductions, methods):
    """The defaults' targets, mesh by mesh: against the best of the attribute-aware peers."""
    if "def" not in methods or not any(p in methods for p in PEERS):
        return
    w("## The targets, mesh by mesh")
    w("")
    w("The defaults against the attribute-aware peers on every coloured mesh: *geo*: the "
      "defaults' geometric RMS (% diagonal) at or below the best peer's; *colour*: their "
      "colour RMS at most 0.95 times the best peer's. The best of meshoptimizer's attribute "
      "mode, its update mode and vtkQuadricDecimation with attributes, and the half-edge peer "
      "alone (meshoptimizer's attribute mode, which keeps input vertices as this filter does).")
    w("")
    w("| mesh | reduction | defaults geo / colour | best peer geo / colour | geo | colour "
      "| half-edge peer geo / colour | ratio (geo, colour) |")
    w("|---|--:|--:|--:|:-:|:-:|--:|--:|")

    def get(mesh, red, mid):
        rec = by.get((mesh, red, mid))
        return figures(rec) if rec and "run" in rec else {}

    for mesh in meshes:
        if mesh not in coloured:
            continue
        for red in reductions:
            d = get(mesh, red, "def")
            peers = [f for f in (get(mesh, red, p) for p in PEERS) if "rms" in f and "crms" in f]
            if "rms" not in d or "crms" not in d or not peers:
                continue
            geo = min(f["rms"] for f in peers)
            col = min(f["crms"] for f in peers)
            attr = get(mesh, red, "meshopt-attr")
            cells = [mesh, f"{red:.0%}", f"{d['rms']:.4f} / {d['crms']:.2f}",
                     f"{geo:.4f} / {col:.2f}", "✓" if d["rms"] <= geo else "✗",
                     "✓" if d["crms"] <= 0.95 * col else "✗"]
            if "rms" in attr and "crms" in attr:
                cells += [f"{attr['rms']:.4f} / {attr['crms']:.2f}",
                          f"{d['rms'] / attr['rms']:.2f}, {d['crms'] / attr['crms']:.2f}"]
            else:
                cells += ["—", "—"]
            w("| " + " | ".join(cells) + " |")
    w("")


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("meshes", nargs="*", help="mesh files (default: every .ply of --data)")
    p.add_argument("--build", default=os.path.join(ROOT, "build"),
                   help="build folder holding bin/color-decimate-run etc. (default: build)")
    p.add_argument("--data", default=os.path.join(os.path.dirname(ROOT), "shared", "data"),
                   help="folder of meshes used when none is given (default: ../shared/data)")
    p.add_argument("--reductions", default="0.9,0.97,0.99",
                   help="comma-separated (default 0.9,0.97,0.99)")
    p.add_argument("--methods", default=",".join(m[0] for m in METHODS),
                   help="comma-separated method ids: " + ", ".join(m[0] for m in METHODS))
    p.add_argument("--work", default=os.path.join(ROOT, "build", "fidelity-benchmark"),
                   help="folder for the simplified meshes and the per-run JSON")
    p.add_argument("--samples", type=int, default=100000,
                   help="Metro samples per side (default 100000)")
    p.add_argument("--size", type=int, default=512, help="render size per view (default 512)")
    p.add_argument("--markdown", default=os.path.join(ROOT, "docs", "RESULTS.md"))
    p.add_argument("--plot", default=os.path.join(ROOT, "docs", "images", "psnr_vs_ratio.png"))
    p.add_argument("--skip", action="append", default=[],
                   help="MESH:REDUCTION:METHOD to leave out (e.g. "
                        "redkitchen_tsdf_7mm:0.97:vtkqd-attr); repeatable")
    p.add_argument("--resume", action="store_true", help="reuse the JSON of earlier runs")
    p.add_argument("--keep-meshes", action="store_true", help="keep the simplified meshes")
    p.add_argument("--extra", action="append", default=[],
                   help="another method, 'ID=LABEL=RUNNER ARGUMENTS' (e.g. 'hec-g10=HalfEdgeColor, "
                        "GeometryWeight 10=--method half-edge-color --geometry-weight 10'); "
                        "repeatable, add its ID to --methods")
    p.add_argument("--rewrite-from", default=None,
                   help="no runs: rewrite the report and the plot from this results.json")
    return p.parse_args()


def tool(build, name):
    path = os.path.join(build, "bin", name)
    if not os.path.exists(path):
        sys.exit(f"fidelity-benchmark: {path} not found (build the project first)")
    return path


def run(cmd, timeout=3600):
    start = time.time()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=timeout)
    return proc, time.time() - start


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def colour_varies(ply):
    """Whether a mesh has a colour array that is not constant (read with the metro tool's
    reader would need VTK: look at the PLY header and a few vertices instead)."""
    try:
        with open(ply, "rb") as f:
            header = b""
            while not header.endswith(b"end_header\n") and len(header) < 65536:
                header += f.readline()
            text = header.decode("latin-1")
            props = [l.split() for l in text.splitlines() if l.startswith("property")]
            names = [p[-1] for p in props if p[1] != "list"]
            if "red" not in names:
                return False
            # Vertex layout (binary): sizes of the scalar properties before the face element.
            sizes = {"char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2,
                     "int16": 2, "uint16": 2, "int": 4, "uint": 4, "int32": 4, "uint32": 4,
                     "float": 4, "float32": 4, "double": 8, "float64": 8}
            vertex_props, in_vertex = [], False
            for line in text.splitlines():
                w = line.split()
                if w and w[0] == "element":
                    in_vertex = w[1] == "vertex"
                elif w and w[0] == "property" and in_vertex:
                    vertex_props.append((w[-1], sizes.get(w[1], 4)))
            stride = sum(s for _, s in vertex_props)
            offset = 0
            for name, s in vertex_props:
                if name == "red":
                    break
                offset += s
            seen = set()
            for _ in range(5000):
                rec = f.read(stride)
                if len(rec) < stride:
                    break
                seen.add(rec[offset:offset + 3])
                if len(seen) > 1:
                    return True
            return False
    except OSError:
        return False


def eval_command(build, original, simplified, out_json, size):
    cmd = [tool(build, "color-decimate-eval"), original, simplified, "--no-lit", "--size",
           str(size), "--json", out_json]
    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run"):
        cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"] + cmd
    return cmd


def measure(args, mesh, name, reduction, method_id, method_args, log):
    folder = os.path.join(args.work, name)
    os.makedirs(folder, exist_ok=True)
    stem = os.path.join(folder, f"{method_id}_{reduction:g}")
    out_mesh, run_json, metro_json, eval_json = (stem + ".vtp", stem + ".run.json",
                                                 stem + ".metro.json", stem + ".eval.json")
    record = {"mesh": name, "reduction": reduction, "method": method_id}
    if not (args.resume and load(run_json)):
        proc, _ = run([tool(args.build, "color-decimate-run"), mesh, out_mesh, "--reduction",
                       str(reduction), "--json", run_json] + method_args)
        if proc.returncode != 0:
            message = (proc.stderr.strip().splitlines() or ["failed"])[-1]
            if proc.returncode == MISSING_PEER:
                record["unavailable"] = message
                log(f"  {method_id}: skipped: {message}")
                return record
            record["error"] = message
            log(f"  {method_id}: FAILED: {record['error']}")
            return record
    record["run"] = load(run_json)
    if not (args.resume and load(metro_json)):
        run([tool(args.build, "color-decimate-metro"), mesh, out_mesh, "--samples",
             str(args.samples), "--json", metro_json, "--quiet"])
    record["metro"] = load(metro_json)
    if not (args.resume and load(eval_json)):
        run(eval_command(args.build, mesh, out_mesh, eval_json, args.size))
    record["eval"] = load(eval_json)
    r, m, e = record["run"], record["metro"], record["eval"]
    msg = f"  {method_id:10s} {r['output_triangles']:>9,} tri {r['seconds']:7.2f} s"
    if m and m.get("ok"):
        msg += f"  geo RMS {m['rms_percent']:.4f} %"
    if e and e.get("unlit"):
        msg += f"  colour RMS {e['unlit']['rms']:.2f}  PSNR {fmt(e['unlit']['psnr'], 2)} dB"
    log(msg)
    done = m and m.get("ok") and e and e.get("unlit")
    if done and os.path.exists(out_mesh) and not args.keep_meshes:
        os.remove(out_mesh)
    return record


def fmt(x, digits):
    if x is None:
        return "—"
    if isinstance(x, float) and (math.isinf(x) or math.isnan(x)):
        return "∞" if x > 0 else "—"
    return f"{x:.{digits}f}"


def figures(rec):
    """The numbers of one record (None where missing)."""
    r, m, e = rec.get("run"), rec.get("metro"), rec.get("eval")
    out = {}
    if r:
        out.update(seconds=r["seconds"], peak=r["peak_bytes"], bpv=r["metric_bytes_per_vertex"],
                   tri_in=r["input_triangles"], tri_out=r["output_triangles"],
                   pts_in=r["input_points"], pts_out=r["output_points"])
    if m and m.get("ok"):
        out.update(mean=m["mean_percent"], rms=m["rms_percent"], max=m["max_percent"])
    if e and e.get("unlit"):
        u = e["unlit"]
        out.update(crms=u["rms"], psnr=u.get("psnr"), common=u.get("common_rms"))
    return out


def markdown_header(w, args, elapsed, skipped):
    """The study's title, command, measures, what was left out and the analysis kept."""
    w("# Fidelity study: the half-edge colour metric against the colour quadric and peers")
    w("")
    w("Written by `Tools/fidelity-benchmark.py` (" + datetime.date.today().isoformat() +
      f", {elapsed / 60:.1f} min on {platform.node() or 'this machine'}: "
      f"{os.cpu_count()} cores shared with other jobs, so times are indicative). Command:")
    w("")
    w("    python3 " + " ".join([os.path.relpath(sys.argv[0], ROOT)] + sys.argv[1:]))
    w("")
    w("Measures (see the script's header): **geometric** distance between original and result "
      "by Metro's method (`color-decimate-metro`: area-uniform samples on both surfaces, "
      f"{args.samples:,} per side, closest-point distance; two-sided = the larger side), as "
      "% of the original's bounding-box diagonal; **colour**: RMS of the per-pixel RGB "
      "distance (0-255) between unlit renders of original and result from the six axis views "
      f"({args.size}² each; pixels covered by either mesh, so silhouette changes count) and "
      "the PSNR of those renders (`color-decimate-eval`, library ColorDecimation::Fidelity); "
      "**time**: wall-clock of the simplification alone (mesh already in memory); **peak**: "
      "resident memory above the level before the run; **B/vertex**: the per-vertex state "
      "of the error metric (the paper's 12 floats = 48 B; the colour quadric's 28 floats = "
      "112 B; vtkQuadricDecimation's sparse quadric of 11 + 4m doubles; meshoptimizer's "
      "11-float quadric).")
    w("")
    if skipped:
        w("Left out: " + "; ".join(skipped) + ".")
        w("")
    # The analysis written by hand between the markers survives a rerun.
    if os.path.exists(args.markdown):
        with open(args.markdown) as f:
            old = f.read()
        a, b = old.find(ANALYSIS_BEGIN), old.find(ANALYSIS_END)
        if a >= 0 and b > a:
            w(old[a:b + len(ANALYSIS_END)])
            w("")


def markdown_table(w, by, reductions, methods, title, cell, mesh_list, note=None):
    """One table of the study: a row per method, a column per mesh, a part per reduction."""
    w(f"## {title}")
    w("")
    if note:
        w(note)
        w("")
    for red in reductions:
        w(f"### {red:.0%} reduction")
        w("")
        w("| method | " + " | ".join(mesh_list) + " |")
        w("|---|" + "--:|" * len(mesh_list))
        for mid in methods:
            row = [METHOD_LABEL[mid]]
            any_value = False
            for mesh in mesh_list:
                rec = by.get((mesh, red, mid))
                text = cell(figures(rec)) if rec and "run" in rec else (
                    "failed" if rec and "error" in rec else "—")
                any_value = any_value or text not in ("—",)
                row.append(text)
            if any_value:
                w("| " + " | ".join(row) + " |")
        w("")


def write_markdown(args, records, meshes, reductions, methods, coloured, elapsed, skipped):
    by = {(r["mesh"], r["reduction"], r["method"]): r for r in records}
    lines = []
    w = lines.append
    markdown_header(w, args, elapsed, skipped)
    rel = os.path.relpath(args.plot, os.path.dirname(os.path.abspath(args.markdown)))
    w(f"![PSNR of the unlit renders against the compression ratio, per coloured mesh]({rel})")
    w("")
    aims(w, by, meshes, coloured, reductions, methods)
    table = functools.partial(markdown_table, w, by, reductions, methods)
    table("Table 1: time and memory",
          lambda f: (f"{f['seconds']:.2f} s / {f['peak'] / 2**20:.0f} MiB / {f['bpv']:.0f} B"
                     f" ({f['tri_out']:,} tri)") if "seconds" in f else "—",
          meshes,
          "Each cell: simplification time / peak memory above the input / the metric's bytes "
          "per vertex (and the output triangle count: a method that stops early is visible "
          "here).")
    table("Table 2: geometric error (Metro), mean / RMS / max, % of the bounding-box diagonal",
          lambda f: (f"{f['mean']:.4f} / **{f['rms']:.4f}** / {f['max']:.3f}")
          if "rms" in f else "—",
          meshes)
    table("Table 3: colour error of unlit renders, RMS (0-255) / PSNR (dB)",
          lambda f: f"**{f['crms']:.2f}** / {fmt(f.get('psnr'), 2)}" if "crms" in f else "—",
          coloured,
          "Meshes whose colour varies (on the others the unlit renders measure silhouettes "
          "only; their figures are in the JSON files).")
    return "\n".join(lines) + "\n"


def plot(args, records, coloured, reductions, methods):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("fidelity-benchmark: matplotlib not found (apt-get install python3-matplotlib): "
              "no plot", file=sys.stderr)
        return
    n = len(coloured)
    if n == 0:
        return
    cols = min(n, 2)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(6.4 * cols, 4.2 * rows), squeeze=False)
    markers = "osD^v<>px*h"
    for i, mesh in enumerate(coloured):
        ax = axes[i // cols][i % cols]
        for j, mid in enumerate(methods):
            pts = []
            for rec in records:
                if rec["mesh"] == mesh and rec["method"] == mid and "run" in rec:
                    f = figures(rec)
                    if f.get("psnr") is not None and f.get("tri_out"):
                        pts.append((f["tri_in"] / f["tri_out"], f["psnr"]))
            if pts:
                pts.sort()
                ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=markers[j % len(markers)],
                        label=METHOD_LABEL[mid])
        ax.set_xscale("log")
        ax.set_title(mesh)
        ax.set_xlabel("compression ratio (input / output triangles)")
        ax.set_ylabel("PSNR of unlit renders (dB)")
        ax.grid(True, which="both", alpha=0.3)
    for k in range(n, rows * cols):
        axes[k // cols][k % cols].axis("off")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=8)
    fig.tight_layout(rect=(0, 0.08 + 0.02 * rows, 1, 1))
    os.makedirs(os.path.dirname(args.plot), exist_ok=True)
    fig.savefig(args.plot, dpi=110)
    print(f"fidelity-benchmark: wrote {args.plot}")


def mesh_name(path):
    return os.path.splitext(os.path.basename(path))[0]


def run_meshes(args, meshes, reductions, methods, log):
    """Every method on every mesh and reduction: the records, the mesh names, those of the
    coloured meshes, and what was left out."""
    records, names, coloured, skipped = [], [], [], []
    skip = set(args.skip)
    unavailable = set()  # methods whose peer is missing: tried once, then left out
    for mesh in meshes:
        name = mesh_name(mesh)
        names.append(name)
        varies = colour_varies(mesh)
        if varies:
            coloured.append(name)
        for red in reductions:
            log(f"{name} at {red:g} ({'coloured' if varies else 'no varying colour'}):")
            for mid in methods:
                spec = next(m for m in METHODS if m[0] == mid)
                if (spec[3] and not varies) or mid in unavailable:
                    continue
                if f"{name}:{red:g}:{mid}" in skip:
                    skipped.append(f"{METHOD_LABEL[mid]} on {name} at {red:.0%} (--skip)")
                    log(f"  {mid}: skipped")
                    continue
                record = measure(args, mesh, name, red, mid, spec[2], log)
                if "unavailable" in record:
                    unavailable.add(mid)
                    skipped.append(f"{METHOD_LABEL[mid]} ({record['unavailable']})")
                    continue
                records.append(record)
    return records, names, coloured, skipped


def main():
    args = parse_args()

    for extra in args.extra:
        parts = extra.split("=", 2)
        if len(parts) != 3:
            sys.exit(f"fidelity-benchmark: --extra wants ID=LABEL=ARGUMENTS, got '{extra}'")
        METHODS.append((parts[0], parts[1], parts[2].split(), False))
        METHOD_LABEL[parts[0]] = parts[1]
    reductions = [float(x) for x in args.reductions.split(",") if x]
    methods = [m for m in args.methods.split(",") if m]
    for m in methods:
        if m not in METHOD_LABEL:
            sys.exit(f"fidelity-benchmark: unknown method '{m}'")
    meshes = args.meshes or sorted(
        os.path.join(args.data, f) for f in os.listdir(args.data) if f.endswith(".ply"))
    if not meshes:
        sys.exit("fidelity-benchmark: no mesh")
    # Large meshes last, so that a time-out leaves the small ones done.
    meshes.sort(key=lambda p: os.path.getsize(p))
    os.makedirs(args.work, exist_ok=True)
    log_path = os.path.join(args.work, "log.txt")
    log_file = open(log_path, "a")

    def log(text):
        print(text, flush=True)
        log_file.write(text + "\n")
        log_file.flush()

    start = time.time()
    if args.rewrite_from:
        # Only the report: from an earlier run's results.
        records, skipped = load(args.rewrite_from) or [], []
        names = [mesh_name(mesh) for mesh in meshes]
        coloured = [mesh_name(mesh) for mesh in meshes if colour_varies(mesh)]
    else:
        records, names, coloured, skipped = run_meshes(args, meshes, reductions, methods, log)
    elapsed = time.time() - start
    meta_path = os.path.join(os.path.dirname(args.rewrite_from or os.path.join(args.work, "x")),
                             "meta.json")
    if not args.rewrite_from:
        with open(os.path.join(args.work, "results.json"), "w") as f:
            json.dump(records, f, indent=1)
        with open(meta_path, "w") as f:
            json.dump({"elapsed": elapsed, "command": sys.argv, "skipped": skipped}, f)
    else:
        meta = load(meta_path) or {}
        elapsed = meta.get("elapsed", elapsed)
        skipped = meta.get("skipped", skipped)
        if meta.get("command"):
            sys.argv = meta["command"]
    text = write_markdown(args, records, names, reductions, methods, coloured, elapsed, skipped)
    os.makedirs(os.path.dirname(args.markdown), exist_ok=True)
    with open(args.markdown, "w") as f:
        f.write(text)
    print(f"fidelity-benchmark: wrote {args.markdown} ({elapsed / 60:.1f} min)")
    plot(args, records, coloured, reductions, methods)


if __name__ == "__main__":
    main()
