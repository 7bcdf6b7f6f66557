#!/usr/bin/python3
"""Charts for docs/ from the CSVs that `sweeptrace accuracy` writes (run by tools/make-docs.sh).

Usage: /usr/bin/python3 tools/charts.py DOCS_DIR
Reads whichever of accuracy.csv, structures.csv, mesh-methods.csv, tessellation.csv,
convergence.csv exist in
DOCS_DIR and writes one PNG per chart beside them. Debian's matplotlib (python3-matplotlib) is
installed for /usr/bin/python3, hence the explicit interpreter.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 1e-9  # zero errors are drawn on this line of the log axes, labelled "0"


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save(fig, docs, name):
    path = os.path.join(docs, name)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    print("wrote", path)


VARIANT_MARKER = {"robust": "o", "thesis": "x", "embree": "^", "embree-robust": "v"}


def speed_vs_error(docs):
    """One row per routine (shape, variant), three aligned panels: errors and speed. Labels are
    the rows' tick labels, so none can overprint another (a scatter of 24 labelled points did)."""
    rows = read(os.path.join(docs, "accuracy.csv"))
    by_routine = {}
    for r in rows:
        by_routine.setdefault((r["shape"], r["variant"]), []).append(r)
    routines = []
    for (shape, variant), rs in sorted(by_routine.items()):
        uniform = [r for r in rs if r["family"] == "uniform"]
        if not uniform:
            continue
        # x: share of rays, over every family, answered wrong beyond rounding (plus leaks);
        # worst p99 relative t error over the families where the answer is a hit on the same
        # surface (uniform, far, huge, tiny); throughput on the uniform family, one thread.
        decided = sum(int(r["rays"]) - int(r["boundary"]) for r in rs if r["family"] != "edges")
        wrong = sum(int(r["wrong_clear"]) for r in rs if r["family"] != "edges")
        leaks = sum(int(r["leaks"]) for r in rs)
        rays_edges = sum(int(r["rays"]) for r in rs if r["family"] == "edges")
        wrong_rate = (wrong + leaks) / max(1, decided + rays_edges)
        t_p99 = max(float(r["t_rel_p99"]) for r in rs if r["family"] in ("uniform", "far", "huge", "tiny"))
        routines.append((shape, variant, wrong_rate, t_p99, float(uniform[0]["mrays_per_s"])))
    shapes = sorted({r[0] for r in routines})
    colours = {s: plt.cm.tab10(i % 10) for i, s in enumerate(shapes)}
    fig, axes = plt.subplots(1, 3, figsize=(13, 0.28 * len(routines) + 1.6), sharey=True)
    ys = list(range(len(routines)))[::-1]
    panels = ((2, "wrong hit/miss beyond rounding + leaks\n(share of rays, all families; 0 drawn at 1e-9)", True),
              (3, "relative t error, p99\n(worst of uniform/far/huge/tiny; 0 drawn at 1e-9)", True),
              (4, "Mrays/s, one thread\n(uniform family)", False))
    for ax, (col, title, floor) in zip(axes, panels):
        for y, r in zip(ys, routines):
            value = max(r[col], FLOOR) if floor else r[col]
            ax.scatter(value, y, color=colours[r[0]], marker=VARIANT_MARKER.get(r[1], "s"), s=45)
        ax.set_xscale("log")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", axis="x", alpha=0.25)
        if floor:
            ax.axvline(FLOOR, color="grey", lw=0.5, ls=":")
            ax.text(FLOOR, ys[0] + 0.6, "0", ha="center", fontsize=8, color="grey")
    axes[0].set_yticks(ys)
    axes[0].set_yticklabels([f"{r[0]} / {r[1]}" for r in routines], fontsize=8)
    axes[0].set_ylim(-0.7, len(routines) - 0.2)
    handles = [plt.Line2D([], [], ls="", marker=m, color="k", label=v) for v, m in VARIANT_MARKER.items()]
    axes[2].legend(handles=handles, fontsize=8, loc="center left", bbox_to_anchor=(1.02, 0.5), title="variant")
    fig.suptitle("Every ray-shape intersector: error and speed (sweeptrace accuracy; one row per routine)")
    save(fig, docs, "speed-vs-error.png")


def structures(docs):
    rows = read(os.path.join(docs, "structures.csv"))
    names = []
    for r in rows:
        if r["structure"] not in names:
            names.append(r["structure"])
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for name in names:
        rs = [r for r in rows if r["structure"] == name]
        x = [int(r["triangles"]) for r in rs]
        axes[0].plot(x, [float(r["mrays_per_s"]) for r in rs], marker="o", label=name)
        axes[1].plot(x, [max(float(r["build_s"]), 1e-6) for r in rs], marker="o", label=name)
    for ax, label in ((axes[0], "Mrays/s, one thread"), (axes[1], "build time, s (wall)")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("triangles (icosphere)")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.2)
    axes[0].legend(fontsize=8)
    fig.suptitle("The thesis's structures redone for rays: speed and build time against size")
    save(fig, docs, "accelerators-vs-size.png")


def mesh_leaks(docs):
    rows = [r for r in read(os.path.join(docs, "mesh-methods.csv")) if int(r["inside_rays"]) > 0]
    if not rows:
        return
    meshes = []
    for r in rows:
        if r["mesh"] not in meshes:
            meshes.append(r["mesh"])
    methods = ["native", "embree", "embree-robust"]
    fig, ax = plt.subplots(figsize=(10, 4.2))
    width = 0.8 / len(methods)
    for i, m in enumerate(methods):
        ys = []
        for mesh in meshes:
            r = next((r for r in rows if r["mesh"] == mesh and r["method"] == m), None)
            ys.append(100.0 * int(r["leaks"]) / int(r["inside_rays"]) if r else 0.0)
        ax.bar([k + i * width for k in range(len(meshes))], ys, width, label=m)
        for k, y in enumerate(ys):
            ax.text(k + i * width, y, "0" if y == 0 else f"{y:.2g}", ha="center", va="bottom", fontsize=7)
    ax.set_xticks([k + width for k in range(len(meshes))])
    ax.set_xticklabels(meshes, fontsize=8)
    ax.set_ylabel("% of rays from inside that escape")
    ax.set_title("Leaks through closed meshes: rays from inside aimed at vertices and edges")
    ax.legend(fontsize=8)
    save(fig, docs, "mesh-leaks.png")


def tessellation(docs):
    rows = read(os.path.join(docs, "tessellation.csv"))
    shapes = []
    for r in rows:
        if r["shape"] not in shapes:
            shapes.append(r["shape"])
    colours = {s: plt.cm.tab10(i % 10) for i, s in enumerate(shapes)}
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for shape in shapes:
        c = colours[shape]
        for accel, ls in (("bvh", "-"), ("embree", "--")):
            mesh = [r for r in rows if r["shape"] == shape and r["accel"] == accel and r["representation"] == "mesh"]
            analytic = [r for r in rows if r["shape"] == shape and r["accel"] == accel and r["representation"] == "analytic"]
            x = [int(r["triangles"]) for r in mesh]
            if accel == "bvh":
                axes[0].plot(x, [max(float(r["rmse_vs_analytic"]), FLOOR) for r in mesh], ls, marker="o", color=c,
                             label=shape)
                if analytic:
                    axes[0].axhline(float(analytic[0]["rmse_vs_converged"]), color=c, lw=0.8, ls=":")
            axes[1].plot(x, [float(r["seconds"]) for r in mesh], ls, marker="o", color=c,
                         label=f"{shape} mesh, {accel}")
            if analytic:
                axes[1].axhline(float(analytic[0]["seconds"]), color=c, lw=0.8, ls=ls)
    axes[0].set_title("image RMSE of the mesh against the analytic render\n(same seed; dotted: the analytic "
                      "render's own noise)", fontsize=9)
    axes[1].set_title("build + render, CPU s (horizontal lines: analytic)", fontsize=9)
    for ax in axes:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("triangles")
        ax.grid(True, which="both", alpha=0.2)
    axes[0].legend(fontsize=8)
    axes[1].legend(fontsize=6)
    fig.suptitle("Model no more than a scene needs: analytic against tessellated")
    save(fig, docs, "tessellated-vs-analytic.png")


def convergence(docs):
    rows = read(os.path.join(docs, "convergence.csv"))
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.6), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for sampling in ("nee-mis", "bsdf-only"):
            for accel, ls in (("bvh", "-"), ("embree", "--")):
                rs = [r for r in rows if r["scene"] == scene and r["sampling"] == sampling and r["accel"] == accel]
                ax.plot([float(r["seconds"]) for r in rs], [float(r["rmse"]) for r in rs], ls, marker="o",
                        label=f"{sampling}, {accel}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("build + render, CPU s (all threads)")
        ax.set_ylabel("RMSE against the reference")
        ax.set_title(scene)
        ax.grid(True, which="both", alpha=0.2)
        ax.legend(fontsize=8)
    fig.suptitle("Convergence: image error against time (1, 2, 4 ... spp)")
    save(fig, docs, "convergence.png")


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit("usage: /usr/bin/python3 tools/charts.py DOCS_DIR")
    docs = sys.argv[1]
    charts = (("accuracy.csv", speed_vs_error), ("structures.csv", structures), ("mesh-methods.csv", mesh_leaks),
              ("tessellation.csv", tessellation), ("convergence.csv", convergence))
    for csv_name, chart in charts:
        if os.path.exists(os.path.join(docs, csv_name)):
            chart(docs)


if __name__ == "__main__":
    main()
