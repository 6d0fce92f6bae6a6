# Draws the capsule analysis report's figures (written by the analyser; do not edit).
# usage: plot_report.py figure_data.json OUT_DIR
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

data = json.load(open(sys.argv[1]))
out = sys.argv[2]
os.makedirs(out, exist_ok=True)

# Figs. 13-14: D_xy against kt with the fitted exponentials; A = t_max, B = t_stop.
for m in data["members"]:
    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    ax.plot(m["kt"], m["D_xy"], "k-", lw=1.0, label="simulation")
    for c in m["curves"]:
        ax.plot(c["kt"], c["D"], "--", lw=1.6, label=c["label"])
    for label, key in (("A", "t_max"), ("B", "t_stop")):
        t = m["markers"].get(key)
        if t is not None:
            ax.axvline(t, color="0.6", lw=0.6, ls=":")
            ax.annotate(label, (t, ax.get_ylim()[1]), ha="center", va="bottom", fontsize=8)
    ax.set_xlabel("kt")
    ax.set_ylabel("$D_{xy}$")
    ax.set_title(m["title"], fontsize=8)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "member_" + m["slug"] + ".png"), dpi=120)
    plt.close(fig)

# Fig. 64: range of the surface shear rate (101) over a power-law membrane, units of k.
for m in data["members"]:
    if "gamma" not in m:
        continue
    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    ax.plot(m["kt"], m["gamma"]["max"], "k-", lw=1.0, label="max")
    ax.plot(m["kt"], m["gamma"]["min"], "k--", lw=1.0, label="min")
    ax.set_xlabel("kt")
    ax.set_ylabel(r"$\gamma / k$")
    ax.set_title(m["title"], fontsize=8)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "member_" + m["slug"] + "_gamma.png"), dpi=120)
    plt.close(fig)

# Figs. 15-20, 25-28, 33-36: characteristic times against the swept parameter.
symbols = ["s", "^", "o", "v", "D", "x"]
for t in data["tables"]:
    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    k = 0
    for case, cdata in t["cases"].items():
        for col, s in cdata["columns"].items():
            if not s["x"]:
                continue
            lo = [y - l for y, l in zip(s["y"], s["lo"])]
            hi = [h - y for y, h in zip(s["y"], s["hi"])]
            ax.errorbar(s["x"], s["y"], yerr=[lo, hi], marker=symbols[k % len(symbols)],
                        ls="-" if k % 2 == 0 else ":", capsize=2, label=(case + ": " if case else "") + col)
            k += 1
    ax.set_xlabel(t["x"])
    ax.set_ylabel(t["ylabel"])
    ax.set_title(t["name"], fontsize=8)
    if k:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, t["name"] + ".png"), dpi=120)
    plt.close(fig)

# Figs. 41-53: central slices at theta = 0, xy-plane (left) and yz-plane (right), one line
# per stored kt; y is vertical in both panels, both drawn to the same scale.
for s in data.get("slices", []):
    fig, axes = plt.subplots(1, 2, figsize=(7.5, 3.8))
    unit = s["unit"]
    lim = 0.0
    for i, shape in enumerate(s["shapes"]):
        color = "C%d" % (i % 10)
        for ax, plane in zip(axes, ("xy", "yz")):
            for j, loop in enumerate(shape[plane]):
                label = "kt = %g" % shape["kt"] if (plane == "xy" and j == 0) else None
                ax.plot(loop["u"], loop["v"], "-", color=color, lw=1.0, label=label)
                lim = max([lim] + [abs(x) for x in loop["u"]] + [abs(x) for x in loop["v"]])
    lim = 1.08 * lim if lim > 0 else 1.0
    for ax, xlabel in zip(axes, ("$x/%s$" % unit, "$z/%s$" % unit)):
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
        ax.set_aspect("equal")
        ax.axhline(0, color="0.85", lw=0.5)
        ax.axvline(0, color="0.85", lw=0.5)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("$y/%s$" % unit)
    axes[0].set_title("xy-plane", fontsize=8)
    axes[1].set_title("yz-plane", fontsize=8)
    if s["shapes"]:
        axes[0].legend(fontsize=7)
    fig.suptitle(s["title"], fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "member_" + s["slug"] + "_slices.png"), dpi=120)
    plt.close(fig)

# Accuracy against cost (block "accuracy"): relative error against core-seconds, log-log,
# every setting labelled, the non-dominated settings joined.
for a in data.get("accuracy", []):
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    p = a["points"]
    ax.loglog(p["cost"], p["error"], "o", color="0.45", label="settings")
    for x, y, label in zip(p["cost"], p["error"], p["label"]):
        ax.annotate(label, (x, y), fontsize=6, xytext=(3, 3), textcoords="offset points")
    f = a["front"]
    if f["cost"]:
        ax.loglog(f["cost"], f["error"], "-o", color="tab:red", lw=1.2, label="non-dominated")
    ax.set_xlabel("cost (core-seconds)")
    ax.set_ylabel("relative error")
    ax.set_title(a["title"], fontsize=8)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, a["name"] + ".png"), dpi=120)
    plt.close(fig)

# Stability (block "stability"): complete and unstable members per pair of swept
# parameters, the kt of blow-up beside each unstable point; log axes for wide positive ranges.
for s in data.get("stability", []):
    fig, ax = plt.subplots(figsize=(5.0, 3.8))
    c, u, o = s["complete"], s["unstable"], s["other"]
    if c["x"]:
        ax.plot(c["x"], c["y"], "o", color="tab:green", label="complete")
    if u["x"]:
        ax.plot(u["x"], u["y"], "x", color="tab:red", ms=8, mew=2, label="unstable")
        for x, y, kt in zip(u["x"], u["y"], u["kt"]):
            if kt is not None:
                ax.annotate("kt = %g" % kt, (x, y), fontsize=6, xytext=(4, -8), textcoords="offset points")
    if o["x"]:
        ax.plot(o["x"], o["y"], "s", color="0.5", mfc="none", label="stopped / no result")
    for axis, key in (("x", "x"), ("y", "y")):
        values = c[key] + u[key] + o[key]
        if values and min(values) > 0 and max(values) / min(values) >= 20:
            (ax.set_xscale if axis == "x" else ax.set_yscale)("log")
    ax.set_xlabel(s["x"])
    ax.set_ylabel(s["y"])
    ax.set_title("stability: " + s["x"] + " and " + s["y"], fontsize=8)
    if c["x"] or u["x"] or o["x"]:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, s["name"] + ".png"), dpi=120)
    plt.close(fig)

# Figs. 7 and 9 (block "published"): members' D_xy (solid) and D_extent (dotted) during the
# shear against the published curves (markers), one colour per curve.
if data.get("published"):
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for k, p in enumerate(data["published"]):
        color = "C%d" % (k % 10)
        ax.plot(p["ref_kt"], p["ref_D"], "o", ms=3, mfc="none", color=color, label=p["curve"])
        for m in p["members"]:
            kt = [t for t in m["kt"] if t <= m["end"]]
            ax.plot(kt, m["D_xy"][:len(kt)], "-", lw=1.0, color=color)
            if "D_extent" in m:
                ax.plot(kt, m["D_extent"][:len(kt)], ":", lw=1.0, color=color)
    ax.set_xlabel("kt")
    ax.set_ylabel("D")
    ax.set_title("members (D_xy solid, D_extent dotted) against published curves (markers)", fontsize=8)
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "published.png"), dpi=120)
    plt.close(fig)
