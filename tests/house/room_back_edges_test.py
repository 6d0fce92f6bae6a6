#!/usr/bin/env python3
"""CMake refuses a back-edge between rooms (cmake/capsule_rooms.cmake).

Configures tiny projects that use the toolkit's own capsule_floor_plan / capsule_room: one
whose rooms depend and include only downwards (it must configure), and ones that declare a
dependency on a room above, include a header of a room above, include a room below that is
not declared, depend on a room not defined yet or not in the plan (each must fail to configure
with its message naming the file, the line and both rooms).
Usage: room_back_edges_test.py SOURCE_DIR [CMAKE]
"""
import pathlib
import subprocess
import sys
import tempfile

PLAN = "capsule_floor_plan(house/a house/b house/c)\n"


def configure(rooms_cmake, cmake, body, files):
    """Writes a project (CMakeLists.txt from `body`, `files` {path: text}); returns (status, output)."""
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp) / "probe"
        for path, text in files.items():
            (root / path).parent.mkdir(parents=True, exist_ok=True)
            (root / path).write_text(text)
        (root / "CMakeLists.txt").write_text(
            "cmake_minimum_required(VERSION 3.20)\nproject(rooms_probe LANGUAGES NONE)\n"
            f"include({rooms_cmake.as_posix()})\n" + PLAN + body)
        run = subprocess.run([cmake, "-S", str(root), "-B", str(root / "build")],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        return run.returncode, " ".join(run.stdout.split())  # CMake wraps long messages


def header(*includes):
    return "#pragma once\n" + "".join(f'#include "{i}"\n' for i in includes)


CASES = [
    # (what, CMake body, files, expected message or None for a configure that must pass)
    ("downward dependencies and includes, also through another room",
     "capsule_room(house/a)\ncapsule_room(house/b DEPENDS house/a)\ncapsule_room(house/c DEPENDS house/b)\n",
     {"house/a/a.hpp": header("generated.hpp"), "house/b/b.hpp": header("house/a/a.hpp"),
      "house/c/c.hpp": header("house/b/b.hpp", "house/a/a.hpp")},
     None),
    ("a declared dependency on a room above",
     "capsule_room(house/a DEPENDS house/b)\ncapsule_room(house/b)\n",
     {"house/a/a.hpp": header(), "house/b/b.hpp": header()},
     "room house/a may not depend on house/b: house/b is above house/a"),
    ("an include of a header of a room above",
     "capsule_room(house/a)\ncapsule_room(house/b DEPENDS house/a)\n",
     {"house/a/a.hpp": header("generated.hpp", "house/b/b.hpp"), "house/b/b.hpp": header()},
     "house/a/a.hpp:3: #include \"house/b/b.hpp\": room house/a may not include room house/b: house/b is above house/a"),
    ("an include of a room below that is not declared",
     "capsule_room(house/a)\ncapsule_room(house/b)\n",
     {"house/a/a.hpp": header(), "house/b/b.hpp": header("house/a/a.hpp")},
     "house/b/b.hpp:2: #include \"house/a/a.hpp\": room house/b includes room house/a, which it does not depend on"),
    ("a dependency on a room below that is not defined yet",
     "capsule_room(house/b DEPENDS house/a)\ncapsule_room(house/a)\n",
     {"house/a/a.hpp": header(), "house/b/b.hpp": header()},
     "room house/b depends on house/a, which is not defined yet"),
    ("a room outside the floor plan",
     "capsule_room(house/a)\ncapsule_room(house/d DEPENDS house/a)\n",
     {"house/a/a.hpp": header(), "house/d/d.hpp": header()},
     "room house/d is not in the floor plan"),
]


def main():
    source = pathlib.Path(sys.argv[1]).resolve()
    cmake = sys.argv[2] if len(sys.argv) > 2 else "cmake"
    rooms_cmake = source / "cmake" / "capsule_rooms.cmake"
    failures = 0
    for what, body, files, expected in CASES:
        status, output = configure(rooms_cmake, cmake, body, files)
        if expected is None:
            ok = status == 0
            why = "" if ok else f"configure failed: {output[-600:]}"
        else:
            ok = status != 0 and expected in output
            why = "" if ok else (f"configure passed" if status == 0 else f"message missing: {expected!r} in {output[-600:]}")
        print(("ok    " if ok else "FAIL  ") + what + (": " + why if why else ""))
        failures += not ok
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
