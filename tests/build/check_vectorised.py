"""The vectorised pair loops stay vectorised (a ctest, not a timing: a loop GCC no longer
if-converts runs at half the speed, as a budget output once did unnoticed).

    python check_vectorised.py CXX SOURCE [--loops-in FILE ...] -I... [flags]

Compiles SOURCE (vector_pairs.cpp) with the plugin's flags and -fopt-info-vec, and requires
the loop of film_only_loop (4 instantiations: grid or not, masses or inverse masses;
lubricated/film_only_loop.h, shared with LIGGGHTS's close pairs), of contact_or_film_loop,
contact_exit_loop and contact_event_loop (6 each: dry, wet, wet with grid; masses or inverse
masses), of film_shear_only_loop (8: as film_only_loop, with and without the budget's records)
and of friction_contact_loop (20: dry; wet with or without a grid and a shear film; masses or
inverse masses; kept contacts or events) to be vectorised in every instantiation: with 64-byte
vectors (the x86-64-v4 clone) and twice with 32-byte vectors (the x86-64-v3 clone, and the v4
clone's epilogue). Each loop is looked up by name in SOURCE and the --loops-in files (the
headers SOURCE includes them from). Exit 77 (skipped) where the clones do not exist: not
GCC >= 12 on x86-64.
"""
import os
import platform
import re
import subprocess
import sys

SKIP = 77
LOOPS = {"film_only_loop": 4, "contact_or_film_loop": 6, "contact_exit_loop": 6, "contact_event_loop": 6,
         "film_shear_only_loop": 8,
         "friction_contact_loop": 20}


def loop_lines(files):
    """(file name, line number) of the first `for (` after each loop template's name."""
    found = {}
    for path in files:
        lines = open(path).read().splitlines()
        for name in LOOPS:
            starts = [n for n, text in enumerate(lines) if re.search(rf"^\s*{name}\(|\b{name}\(const ", text)]
            if starts and name not in found:
                start = starts[0]
                found[name] = (os.path.basename(path),
                               next(n for n in range(start, len(lines)) if "for (" in lines[n]) + 1)
    missing = set(LOOPS) - set(found)
    if missing:
        raise SystemExit(f"loops not found in {files}: {sorted(missing)}")
    return found


def main():
    cxx, source, rest = sys.argv[1], sys.argv[2], sys.argv[3:]
    files, flags = [source], []
    while rest:
        argument = rest.pop(0)
        if argument == "--loops-in":
            files.append(rest.pop(0))
        else:
            flags.append(argument)
    if platform.machine() != "x86_64":
        return SKIP
    version = subprocess.run([cxx, "-dumpfullversion"], capture_output=True, text=True).stdout
    is_gcc = "clang" not in subprocess.run([cxx, "--version"], capture_output=True, text=True).stdout
    if not is_gcc or int(version.split(".")[0] or 0) < 12:
        return SKIP
    report = subprocess.run([cxx, *flags, "-c", source, "-o", "/dev/null", "-fopt-info-vec-optimized"],
                            capture_output=True, text=True)
    if report.returncode != 0:
        print(report.stderr)
        return 1
    failed = False
    for name, (file_name, line) in loop_lines(files).items():
        for width, per_instantiation in ((32, 2), (64, 1)):
            count = len(re.findall(rf"{re.escape(file_name)}:{line}:\d+: optimized: loop vectorized using {width} byte vectors",
                                   report.stderr))
            ok = count >= per_instantiation * LOOPS[name]
            failed |= not ok
            print(f"{name} ({file_name}:{line}): {count} loops of {per_instantiation * LOOPS[name]} vectorised with "
                  f"{width}-byte vectors{'' if ok else '  <- FAILED'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
