# Draws the capsule analysis report's figures (written by the analyser; do not edit).
# usage: plot_report.py figure_data.json OUT_DIR
# Each PNG is one declaration of figure_data.json's "figures" (analysis/report/figure_declarations.hpp):
# its quantities on x, left and right y and extra panels, its series, and the dissertation's
# figure number when it stands for one; the blocks (members, tables, ...) hold the numbers.
import json
import math
import os
import re
import sys
import textwrap

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

data = json.load(open(sys.argv[1]))
out = sys.argv[2]
os.makedirs(out, exist_ok=True)

# Quantities and parameters in words with their symbols.
WORDS = {
    "kt": "time $kt$",
    "D_xy": "Taylor deformation $D_{xy}$",
    "lambda": r"extension ratio $\lambda = D_{axial} / D_{transverse}$",
    "D": "Taylor deformation $D$",
    "k tau_s": r"response time $k\tau_s$",
    "k tau_r": r"recovery time $k\tau_r$",
    "k tau_R1": r"first-phase recovery time $k\tau_{R1}$",
    "k tau_R2": r"second-phase recovery time $k\tau_{R2}$",
    "tau_s/tau_e": r"normalised response time $\tau_s/\tau_e$",
    "tau_r/tau_e": r"normalised recovery time $\tau_r/\tau_e$",
    "tau_s/tau_v": r"normalised response time $\tau_s/\tau_v$",
    "tau_r/tau_v": r"normalised recovery time $\tau_r/\tau_v$",
    "tau_s (s)": r"response time $\tau_s$ (s)",
    "tau_r (s)": r"recovery time $\tau_r$ (s)",
    "tau_R1 (s)": r"first-phase recovery time $\tau_{R1}$ (s)",
    "tau_R2 (s)": r"second-phase recovery time $\tau_{R2}$ (s)",
    "w_R1": r"fast phase's share $w_{R1}$ (fraction)",
    "k t_c": r"extensional recovery time $k t_c$",
    "t_c/tau_v": r"normalised extensional recovery time $t_c / (\mu_s / G_s)$",
    "t_c (s)": r"extensional recovery time $t_c$ (s)",
    "physical.membrane_viscosity_uN_s_per_m": r"membrane viscosity $\mu_s$ ($\mu$N s/m)",
    "physical.shear_modulus_uN_per_m": r"shear modulus $G_s$ ($\mu$N/m)",
    "physical.shear_rate_per_s": r"shear rate $k$ (1/s)",
    "gamma_max": r"maximum surface shear rate $\gamma_{max}/k$",
    "gamma_min": r"minimum surface shear rate $\gamma_{min}/k$",
    "theta": r"inclination $\theta$ (rad)",
    "Ca": "capillary number $Ca$",
    "E_b": "bending stiffness $E_b$",
    "V": "viscosity ratio $V$",
    "eta": r"membrane viscosity ratio $\eta$",
    "Re": "Reynolds number $Re$",
    "resolution.a": "radius $a$ (lattice units)",
    "resolution.tau": r"relaxation time $\tau$ (lattice units)",
    "resolution.mesh_level": "mesh level",
    "resolution.segments": "segments",
    "power_law.n": "power-law index $n$",
    "power_law.K": "power-law consistency $K$",
    "cost": "cost (core-seconds)",
    "relative error": "relative error",
}
SYMBOL = {  # short forms for legends
    "k tau_s": r"$k\tau_s$", "k tau_r": r"$k\tau_r$", "k tau_R1": r"$k\tau_{R1}$", "k tau_R2": r"$k\tau_{R2}$",
    "tau_s/tau_e": r"$\tau_s/\tau_e$", "tau_r/tau_e": r"$\tau_r/\tau_e$", "tau_s/tau_v": r"$\tau_s/\tau_v$",
    "tau_r/tau_v": r"$\tau_r/\tau_v$", "w_R1": r"$w_{R1}$", "k t_c": r"$k t_c$", "t_c/tau_v": r"$t_c/\tau_v$",
    "t_c (s)": r"$t_c$ (s)",
}
FITS = {  # fit names in words
    "response": "response (85)", "recovery": "recovery (86)", "two_phase": "two phases (87)-(89)",
    "double_exponential": "double exponential (90)", "double_exponential_free": "double exponential, free amplitudes",
}
MARKER_AB = "A: $t_{max}$, largest $D_{xy}$ in shear; B: $t_{stop}$, shear stopped (as the text's Fig. 13)"


def words(key):
    return WORDS.get(key, key)


# The symbols of figures.md's plain text, typeset: "k tau_R1" -> $k\tau_{R1}$.
TITLE_SYMBOLS = [(r"\bk tau_(R1|R2|s|r)\b", r"$k\\tau_{\1}$"), (r"\btau_(s|r)/tau_(e|v)\b", r"$\\tau_\1/\\tau_\2$"),
                 (r"(?<!\\)\btau_(e|v|s|r)\b", r"$\\tau_\1$"), (r"\bD_xy\b", r"$D_{xy}$"), (r"\bE_b\b", r"$E_b$"),
                 (r"\beta\b", r"$\\eta$"), (r"\bmu_(a|s)\b", r"$\\mu_\1$"), (r"\btheta\b", r"$\\theta$"),
                 (r"\bgamma\b", r"$\\gamma$"), (r"-pi/3\b", r"$-\\pi/3$"), (r"\bpi/6\b", r"$\\pi/6$"),
                 (r"\bkt\b", r"$kt$"), (r"\bCa\b", r"$Ca$"), (r"\b(K|n|V|G)\b(?= [0-9]| against| varied)", r"$\1$"),
                 (r"\bc0\b", r"$c_0$"), (r"\bkappa\b", r"$\\kappa$")]


def typeset(text):
    for pattern, replacement in TITLE_SYMBOLS:
        text = re.sub(pattern, replacement, text)
    return text


def title_of(decl, fallback):
    if decl.get("number"):
        return typeset("Fig. %s: %s" % (decl["number"], decl["shows"]))
    return fallback


def sig(x, digits):
    """x to `digits` significant figures, as text."""
    if x == 0 or not math.isfinite(x):
        return "%g" % x
    return "%.*f" % (max(0, digits - 1 - int(math.floor(math.log10(abs(x))))), x)


def with_interval(value, lo, hi):
    """'0.285 ± 0.004': the half-width to two significant figures, the value to the same place."""
    if value is None:
        return "n/a"
    if lo is None or hi is None:
        return sig(value, 3)
    hw = 0.5 * (hi - lo)
    if hw <= 0 or not math.isfinite(hw):
        return sig(value, 3)
    places = max(0, 1 - int(math.floor(math.log10(hw))))
    return "%.*f ± %.*f" % (places, value, places, hw)


def legend_outside(ax, handles=None, labels=None, right_axis=False):
    if handles is None:
        handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(handles, labels, fontsize=7, loc="upper left", bbox_to_anchor=(1.24 if right_axis else 1.02, 1.0),
                  borderaxespad=0.0, frameon=False)


def save(fig, name, caption=None):
    if caption:
        fig.text(0.01, -0.02, "\n".join(textwrap.wrap(caption, 110)), fontsize=7, ha="left", va="top")
    fig.savefig(os.path.join(out, name), dpi=120, bbox_inches="tight")
    plt.close(fig)


members = {}
for m in data.get("members", []):
    members.setdefault(m["slug"], m)
tables = {t["name"]: t for t in data.get("tables", [])}
slices = {s["slug"]: s for s in data.get("slices", [])}
accuracy = {a["name"]: a for a in data.get("accuracy", [])}
stability = {s["name"]: s for s in data.get("stability", [])}


def fit_label(c):
    """A fitted curve's legend: the fit in words, each parameter with its 95 % interval."""
    if "parameters" not in c:
        return c["label"]
    parts = []
    for p in c["parameters"]:
        name = p["name"].replace("k_tau_", "k tau_")
        parts.append("%s = %s" % (SYMBOL.get(name, name), with_interval(p["value"], p["ci_low"], p["ci_high"])))
    return FITS.get(c["model"], c["model"]) + ":\n" + ", ".join(parts)


def draw_ab(ax, m, marks=(("A", "t_max"), ("B", "t_stop"))):
    for label, key in marks:
        t = m["markers"].get(key)
        if t is not None:
            ax.axvline(t, color="0.6", lw=0.6, ls=":")
            ax.annotate(label, (t, 1.0), xycoords=("data", "axes fraction"), ha="center", va="bottom", fontsize=8)


# Figs. 13-14 and each member: D_xy against kt with the fitted exponentials (intervals 95 %).
def draw_member(decl):
    m = members[decl["source"]]
    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    # A stretch member carries its extension ratio ("y"): drawn instead of D_xy, with its fit.
    y = m.get("y", {"name": "D_xy", "values": m["D_xy"]})
    ax.plot(m["kt"], y["values"], "k-", lw=1.0, label="simulation")
    for c in m["curves"]:
        ax.plot(c["kt"], c["D"], "--", lw=1.6, label=fit_label(c))
    stretch = y["name"] != "D_xy"
    draw_ab(ax, m, (("B", "t_stop"),) if stretch else (("A", "t_max"), ("B", "t_stop")))
    ax.set_xlabel(words("kt"))
    ax.set_ylabel(words(y["name"]))
    what = "Extension ratio" if stretch else "Taylor deformation"
    ax.set_title(title_of(decl, what + " against time: " + m["title"]), fontsize=9, pad=14)
    legend_outside(ax)
    marks = "B: $t_{stop}$, the load released" if stretch else MARKER_AB
    save(fig, decl["file"], marks + "; fitted values with 95 % intervals (Student's t).")


# Fig. 64: range of the surface shear rate (101) over a power-law membrane, units of k.
def draw_gamma(decl):
    m = members[decl["source"]]
    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    ax.plot(m["kt"], m["gamma"]["max"], "k-", lw=1.0, label="maximum")
    ax.plot(m["kt"], m["gamma"]["min"], "k--", lw=1.0, label="minimum")
    ax.set_xlabel(words("kt"))
    ax.set_ylabel(r"surface shear rate $\gamma/k$")
    ax.set_title(title_of(decl, "Surface shear rate range against time: " + m["title"]), fontsize=9)
    legend_outside(ax)
    save(fig, decl["file"])


# Figs. 15-20, 25-28, 33-36: characteristic times against the swept parameter. Colour per series
# (a case, or a level of a resolution ladder: separate markers, never one line); marker and line
# per quantity as the text draws them; free-amplitude fits open; fractions in their own panel;
# a right axis at decl["right_scale"] times the left.
QUANTITY_STYLE = {"k tau_s": ("s", "-"), "k tau_r": ("^", ":"), "k tau_R1": ("^", "-"), "k tau_R2": ("s", ":"),
                  "tau_s/tau_e": ("s", "-"), "tau_r/tau_e": ("^", ":"), "tau_s/tau_v": ("s", "-"),
                  "tau_r/tau_v": ("^", ":"), "w_R1": ("o", "--")}


def draw_times(decl):
    t = tables[decl["source"]]
    panels = decl["panels"]
    heights = [2.2] + [1.3 if p["right"] else 1.0 for p in panels]
    fig, axes = plt.subplots(len(heights), 1, figsize=(6.0, 3.4 + 2.0 * len(panels)), sharex=True,
                             gridspec_kw={"height_ratios": heights}, squeeze=False)
    axes = [a[0] for a in axes]
    names = ["main"] + [p["label"] for p in panels]
    quantities = [decl] + panels
    right = {n: (axes[i].twinx() if quantities[i]["right"] else None) for i, n in enumerate(names)}
    left = dict(zip(names, axes))
    tops = {(n, a): 0.0 for n in names for a in ("left", "right")}
    several = len(decl["series"]) > 1
    quantity_colors = {}
    # A resolution ladder's levels of one case share its colour; the finest level is filled,
    # coarser levels open.
    level = re.compile(r"(, )?\ba = ([0-9.]+)")
    bases, finest = [], {}
    for s in decl["series"]:
        base = level.sub("", s["label"]).replace("()", "").strip()
        m = level.search(s["label"])
        if base not in bases:
            bases.append(base)
        if m:
            finest[base] = max(finest.get(base, 0.0), float(m.group(2)))
    for i, s in enumerate(decl["series"]):
        base = level.sub("", s["label"]).replace("()", "").strip()
        m = level.search(s["label"])
        coarse = bool(m) and float(m.group(2)) < finest.get(base, 0.0)
        for c in s["columns"]:
            d = t["cases"][s["label"]]["columns"][c["column"]]
            panel = c.get("panel", "main")
            target = right[panel] if c["axis"] == "right" else left[panel]
            marker, ls = QUANTITY_STYLE.get(c["quantity"], ("o", "-"))
            free = c["fit"].endswith("_free")
            if several:
                color = "C%d" % (bases.index(base) % 10)
            else:
                color = quantity_colors.setdefault(c["quantity"], "C%d" % (len(quantity_colors) % 10))
            lo = [max(0.0, y - l) for y, l in zip(d["y"], d["lo"])]
            hi = [max(0.0, h - y) for y, h in zip(d["y"], d["hi"])]
            label = SYMBOL.get(c["quantity"], c["quantity"])
            if panel != "main":
                label += " (" + panel + ")"
            if c["axis"] == "right":
                label += ", right axis"
            if several:
                label += ": " + ("" if s["label"].startswith("(") else "case ") + s["label"]
            target.errorbar(d["x"], d["y"], yerr=[lo, hi], marker=marker, ls=ls, color=color, capsize=2, ms=5,
                            mfc="none" if free or coarse else color, alpha=0.6 if coarse else 1.0, label=label)
            tops[(panel, c["axis"])] = max([tops[(panel, c["axis"])]] + d["hi"] + d["y"])
    axes[-1].set_xlabel(words(decl["x"]))
    handles, labels = [], []
    for i, n in enumerate(names):
        q = quantities[i]
        ax, rax = left[n], right[n]
        if n == "fraction":
            ax.set_ylabel(", ".join(SYMBOL.get(v, v) for v in q["left"]) + "\n(fraction)")
            ax.set_ylim(0.0, 1.05)
        elif q["left"] and n == "main":
            ax.set_ylabel("\n".join(words(v) for v in q["left"]))
        elif q["left"]:
            ax.set_ylabel(", ".join(SYMBOL.get(v, v) for v in q["left"]) + "\n(" + n + ")")
        if rax is not None:
            scale = decl.get("right_scale", 100)
            top = 1.08 * max(tops[(n, "left")], tops[(n, "right")] / scale, 1e-12)
            ax.set_ylim(0.0, top)
            rax.set_ylim(0.0, scale * top)
            rax.set_ylabel(("\n".join(words(v) for v in q["right"]) if n == "main" else
                            ", ".join(SYMBOL.get(v, v) for v in q["right"])) + "\n(right axis: %g × left)" % scale)
        for a in (ax, rax):
            if a is not None:
                h, l = a.get_legend_handles_labels()
                handles, labels = handles + h, labels + l
    fallback = "%s against %s" % (", ".join(words(q) for q in decl["left"] + decl["right"]), words(decl["x"]))
    axes[0].set_title(title_of(decl, fallback[0].upper() + fallback[1:]), fontsize=9)
    legend_outside(axes[0], handles, labels, right_axis=bool(decl["right"]))
    caption = "Points: fitted values with 95 % intervals (Student's t)."
    if finest:
        caption += " Levels of a resolution ladder (a = radius in lattice units): finest filled, coarser open."
    if "free-amplitude fit" in names:
        caption += " Middle: the same times from the double exponential with free amplitudes (open markers)."
    if "fraction" in names:
        caption += " Lower panel: the fast phase's share of the change, a fraction, not a time."
    save(fig, decl["file"], caption)


# Figs. 41-53: central slices at theta = 0, xy-plane (left) and yz-plane (right), one line
# per stored kt; y is vertical in both panels, both drawn to the same scale.
def draw_slices(decl):
    s = slices[decl["source"]]
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
        legend_outside(axes[1], *axes[0].get_legend_handles_labels())
    fig.suptitle(title_of(decl, "Central slices of the capsule: " + s["title"]), fontsize=9)
    save(fig, decl["file"])


# Accuracy against cost (block "accuracy"): relative error against core-seconds, log-log,
# every setting labelled, the non-dominated settings joined.
def draw_accuracy(decl):
    a = accuracy[decl["source"]]
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    p = a["points"]
    ax.loglog(p["cost"], p["error"], "o", color="0.45", label="settings")
    for x, y, label in zip(p["cost"], p["error"], p["label"]):
        ax.annotate(label, (x, y), fontsize=6, xytext=(3, 3), textcoords="offset points")
    f = a["front"]
    if f["cost"]:
        ax.loglog(f["cost"], f["error"], "-o", color="tab:red", lw=1.2, label="non-dominated")
    ax.set_xlabel(words("cost"))
    ax.set_ylabel(words("relative error"))
    ax.set_title(title_of(decl, "Relative error against cost: " + a["title"]), fontsize=9)
    legend_outside(ax)
    save(fig, decl["file"])


# Stability (block "stability"): complete and unstable members per pair of swept
# parameters, the kt of blow-up beside each unstable point; log axes for wide positive ranges.
def draw_stability(decl):
    s = stability[decl["source"]]
    fig, ax = plt.subplots(figsize=(5.0, 3.8))
    c, u, o = s["complete"], s["unstable"], s["other"]
    if c["x"]:
        ax.plot(c["x"], c["y"], "o", color="tab:green", label="complete")
    if u["x"]:
        ax.plot(u["x"], u["y"], "x", color="tab:red", ms=8, mew=2, label="unstable (kt of blow-up beside)")
        for x, y, kt in zip(u["x"], u["y"], u["kt"]):
            if kt is not None:
                ax.annotate("kt = %g" % kt, (x, y), fontsize=6, xytext=(4, -8), textcoords="offset points")
    if o["x"]:
        ax.plot(o["x"], o["y"], "s", color="0.5", mfc="none", label="stopped / no result")
    for axis, key in (("x", "x"), ("y", "y")):
        values = c[key] + u[key] + o[key]
        if values and min(values) > 0 and max(values) / min(values) >= 20:
            (ax.set_xscale if axis == "x" else ax.set_yscale)("log")
    ax.set_xlabel(words(s["x"]))
    ax.set_ylabel(words(s["y"]))
    ax.set_title(title_of(decl, "Stability over %s and %s" % (words(s["x"]), words(s["y"]))), fontsize=9)
    legend_outside(ax)
    save(fig, decl["file"])


# Figs. 7 and 9 (block "published"): members' D_xy (solid) and D_extent (dotted) during the
# shear against the published curves (markers), one colour per curve.
def draw_published(decl):
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for k, p in enumerate(data["published"]):
        color = "C%d" % (k % 10)
        ax.plot(p["ref_kt"], p["ref_D"], "o", ms=3, mfc="none", color=color, label=p["curve"])
        for m in p["members"]:
            kt = [t for t in m["kt"] if t <= m["end"]]
            ax.plot(kt, m["D_xy"][:len(kt)], "-", lw=1.0, color=color)
            if "D_extent" in m:
                ax.plot(kt, m["D_extent"][:len(kt)], ":", lw=1.0, color=color)
    ax.set_xlabel(words("kt"))
    ax.set_ylabel(words("D"))
    ax.set_title(title_of(decl, "Taylor deformation against time, members against published curves"), fontsize=9)
    legend_outside(ax)
    save(fig, decl["file"], "Markers: published curves; lines: the members, $D_{xy}$ solid and $D$ from the "
         "extents dotted, one colour per curve.")


# Block "experiments": the experiment's means with their spread as error bars, a colour per
# measured quantity, and the members' values joined by lines, a line style per group (resolution).
def draw_experiment(decl):
    e = next(x for x in data["experiments"] if x["name"] == decl["source"])
    fig, ax = plt.subplots(figsize=(6.0, 3.8))
    colors = {}
    for k, q in enumerate(e["quantities"]):
        colors[q["measured"]] = "C%d" % (k % 10)
        ax.errorbar(q["x"], q["mean"], yerr=q["spread"], fmt="o", ms=4, capsize=3, color=colors[q["measured"]],
                    label="measured: " + column_words(q["measured"]))
    groups = []
    for line in e["lines"]:
        if line["group"] not in groups:
            groups.append(line["group"])
    styles = ["-", "--", ":", "-."]
    for line in e["lines"]:
        if line["x"]:
            ax.plot(line["x"], line["y"], styles[groups.index(line["group"]) % len(styles)], marker="x", ms=4,
                    lw=1.0, color=colors[line["measured"]],
                    label="toolkit: " + column_words(line["measured"]) + ", " + typeset(line["group"]))
    ax.set_xlabel(column_words(e["x"]))
    unit = column_unit(e["quantities"][0]["measured"]) if e["quantities"] else ""
    ax.set_ylabel("diameter" + (" (%s)" % unit if unit else "") if all("diameter" in q["measured"]
                  for q in e["quantities"]) else "value")
    ax.set_title(title_of(decl, "Members against the experiment: " + e["source"]), fontsize=9)
    legend_outside(ax)
    save(fig, decl["file"], "Circles with error bars: the experiment's means and standard deviations; crosses "
         "joined by lines: the toolkit's members where their first phase ended, a line style per " +
         ("group (%s)." % ", ".join(typeset(g) for g in groups)))


UNITS = {"pN": "pN", "um": r"$\mu$m", "s": "s", "per_s": "1/s", "Hz": "Hz", "deg": "degrees"}


def column_unit(name):
    """The unit a data column's name ends with: "axial_diameter_um" -> "um" typeset."""
    for suffix in sorted(UNITS, key=len, reverse=True):
        if name.endswith("_" + suffix):
            return UNITS[suffix]
    return ""


def column_words(name):
    """A data column in words: "force_pN" -> "force (pN)", "axial_diameter_um" -> "axial diameter (um)"."""
    unit = column_unit(name)
    stem = name
    for suffix in UNITS:
        if UNITS[suffix] == unit and name.endswith("_" + suffix):
            stem = name[: -len(suffix) - 1]
    return stem.replace("_", " ") + (" (%s)" % unit if unit else "")


# Members drawn together as one figure of the text draws them (e.g. Fig. 62, the power law solid
# and its Kelvin-Voigt partners dotted; Fig. 63 their inclinations): a line style per group (the
# levels of a resolution ladder are groups), a colour per member in it, where the shear stopped.
# One group: a line style and a colour per member (as the text's Fig. 60), so equal curves stay
# visible; groups of one member each: a colour per group.
def draw_together(decl):
    quantity = decl["left"][0]
    groups = decl["source"]
    fig, ax = plt.subplots(figsize=(6.0, 3.8))
    styles = ["-", "--", ":", "-."] if len(groups) == 1 else ["-", ":", "--", "-."]
    single = all(len(g["members"]) == 1 for g in groups)
    stops = []  # (kt, value, colour) where a member's shear stopped before its end
    for g, group in enumerate(groups):
        ms = [members[slug] for slug in group["members"]]
        for i, (m, name) in enumerate(zip(ms, member_names(ms))):
            color = "C%d" % ((g if single else i) % 10)
            style = styles[(i if len(groups) == 1 else g) % len(styles)]
            t_stop, t_end = m["markers"].get("t_stop"), m["markers"].get("t_end", m["kt"][-1])
            kt, y = shear_inclination(m, t_stop) if quantity == "theta" else (m["kt"], m[quantity])
            ax.plot(kt, y, style, color=color, lw=1.2, label=typeset(group["label"]) + (", " + name if name else ""))
            if quantity != "theta" and t_stop is not None and t_stop < t_end - 1e-6 * max(1.0, abs(t_end)):
                k = min(range(len(m["kt"])), key=lambda j: abs(m["kt"][j] - t_stop))
                stops.append((m["kt"][k], m[quantity][k], color))
    if len(groups) == 1:
        caption = typeset(groups[0]["label"]) + ": a line style and a colour per member."
    else:
        caption = "; ".join("%s: %s lines" % (typeset(group["label"]), STYLE_WORDS[styles[g % len(styles)]])
                            for g, group in enumerate(groups)) + "."
    if any(re.match(r"a = [0-9.]+$", group["label"]) for group in groups):
        caption += " $a$: the capsule's radius in lattice units, a level of the resolution ladder."
    if quantity == "theta":
        caption += (" The inclination during the shear, where $D_{xy}$ > %g: an undeformed or relaxed sphere has no "
                    "major axis, so the recovery is not drawn." % MIN_D_FOR_THETA)
    caption += mark_stops(ax, stops)
    if decl.get("otherwise"):
        caption += " " + otherwise_sentence(decl["otherwise"])
    ax.set_xlabel(words("kt"))
    ax.set_ylabel(words(quantity))
    ax.set_title(title_of(decl, words(quantity)[0].upper() + words(quantity)[1:] + " against time"), fontsize=9)
    legend_outside(ax)
    save(fig, decl["file"], caption)


def member_names(ms):
    """Each member's legend name within its group: the parameters that differ in it ("$E_b$ = 0.05")."""
    keys = sorted({k for m in ms for k in m.get("parameters", {})
                   if len({m2.get("parameters", {}).get(k) for m2 in ms}) > 1})
    names = [", ".join(parameter_text(k, m["parameters"][k]) for k in keys if k in m["parameters"]) for m in ms]
    return [n or (m["slug"] if len(ms) > 1 else "") for n, m in zip(names, ms)]


def mark_stops(ax, stops):
    """One vertical line where the members' shear stopped together (within 2 %), else an open circle
    on each curve; returns the caption's sentence."""
    if not stops:
        return ""
    times = [t for t, _, _ in stops]
    if max(times) - min(times) <= 0.02 * max(abs(t) for t in times):
        ax.axvline(sum(times) / len(times), color="0.5", lw=0.8, ls="-", zorder=0)
        return " Vertical line: the shear stopped ($kt$ = %.3g)." % (sum(times) / len(times))
    for t, y, color in stops:
        ax.plot([t], [y], "o", mfc="none", color=color, ms=5)
    return " Open circles: where each member's shear stopped."


STYLE_WORDS = {"-": "solid", ":": "dotted", "--": "dashed", "-.": "dash-dot"}
SHORT = {"power_law.K": "$K$", "power_law.n": "$n$", "eta": r"$\eta$", "resolution.a": "$a$",
         "Ca": "$Ca$", "E_b": "$E_b$", "V": "$V$", "G": "$G$", "c0": "$c_0$"}


MIN_D_FOR_THETA = 1e-3  # below it the major axis, and so theta, is not defined to plotting accuracy


def shear_inclination(m, t_stop):
    """theta while the shear runs (kt <= t_stop) and the capsule is deformed (D_xy > MIN_D_FOR_THETA)."""
    keep = [j for j, t in enumerate(m["kt"])
            if (t_stop is None or t <= t_stop) and m["D_xy"][j] > MIN_D_FOR_THETA]
    return [m["kt"][j] for j in keep], [m["theta"][j] for j in keep]


def otherwise_sentence(text):
    """figure_axes.md's "without X: why" / "with X: why" as a caption's sentence."""
    head, _, why = text.partition(": ")
    for prefix, words_ in (("without ", "Not drawn, unlike the text: "), ("with ", "Added to the text's figure: ")):
        if head.startswith(prefix):
            return typeset("%s%s (%s)." % (words_, head[len(prefix):], why))
    return typeset("Unlike the text: %s (%s)." % (head, why))


def parameter_text(key, value):
    """A member's parameter in a legend: "$E_b$ = 0.05"; a mesh level as its triangles (20 x 4^level)."""
    if key == "resolution.mesh_level":
        return "%d triangles" % (20 * 4 ** int(round(value)))
    return "%s = %g" % (SHORT.get(key, key.split(".")[-1]), value)


DRAW = {"member": draw_member, "gamma": draw_gamma, "times": draw_times, "slices": draw_slices,
        "accuracy": draw_accuracy, "stability": draw_stability, "published": draw_published,
        "together": draw_together, "experiment": draw_experiment}
for decl in data.get("figures", []):
    DRAW[decl["kind"]](decl)
