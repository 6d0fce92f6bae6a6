#include "analysis/plot_script.hpp"

#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>

namespace capsule::analysis {

namespace {
std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  if (status == -1) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

const std::string& plot_script_text() {
  static const std::string text = R"py(# Draws the capsule analysis report's figures (written by the analyser; do not edit).
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
)py";
  return text;
}

std::string run_plot_script(const std::string& script_path, const std::string& data_path, const std::string& out_dir,
                            const std::string& python) {
  if (!std::filesystem::exists(python)) return "figures skipped: " + python + " not found";
  if (run(shell_quote(python) + " -c 'import matplotlib' >/dev/null 2>&1") != 0)
    return "figures skipped: " + python + " has no matplotlib";
  const std::string log = (std::filesystem::path(out_dir) / "plot_report.log").string();
  const int rc = run(shell_quote(python) + " " + shell_quote(script_path) + " " + shell_quote(data_path) + " " +
                     shell_quote(out_dir) + " >" + shell_quote(log) + " 2>&1");
  if (rc != 0) return "figures skipped: the plotting script failed (exit " + std::to_string(rc) + "), see " + log;
  return "";
}

}  // namespace capsule::analysis
