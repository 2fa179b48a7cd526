"""The vectorised pair loops stay vectorised (a ctest, not a timing: a loop GCC no longer
if-converts runs at half the speed, as a budget output once did unnoticed).

    python check_vectorised.py CXX SOURCE -I... [flags]

Compiles SOURCE (vector_pairs.cpp) with the plugin's flags and -fopt-info-vec, and requires
the loop of film_only_loop (4 instantiations: grid or not, masses or inverse masses), of
contact_or_film_loop, contact_exit_loop and contact_event_loop (6 each: dry, wet, wet with grid; masses or inverse masses), of
film_shear_only_loop (8: as film_only_loop, with and without the budget's records) and of friction_contact_loop (10: dry; wet with or
without a grid and a shear film; masses or inverse masses) to be vectorised in every instantiation: with 64-byte vectors (the
x86-64-v4 clone) and twice with 32-byte vectors (the x86-64-v3 clone, and the v4 clone's
epilogue). Exit 77 (skipped) where the clones do not exist: not GCC >= 12 on x86-64.
"""
import platform
import re
import subprocess
import sys

SKIP = 77
LOOPS = {"film_only_loop": 4, "contact_or_film_loop": 6, "contact_exit_loop": 6, "contact_event_loop": 6,
         "film_shear_only_loop": 8,
         "friction_contact_loop": 20}


def loop_lines(source):
    """Line number of the first `for (` after each loop template's name."""
    lines = open(source).read().splitlines()
    found = {}
    for name in LOOPS:
        start = next(n for n, text in enumerate(lines) if re.search(rf"\b{name}\(", text))
        found[name] = next(n for n in range(start, len(lines)) if "for (" in lines[n]) + 1
    return found


def main():
    cxx, source, flags = sys.argv[1], sys.argv[2], sys.argv[3:]
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
    for name, line in loop_lines(source).items():
        for width, per_instantiation in ((32, 2), (64, 1)):
            count = len(re.findall(rf":{line}:\d+: optimized: loop vectorized using {width} byte vectors",
                                   report.stderr))
            ok = count >= per_instantiation * LOOPS[name]
            failed |= not ok
            print(f"{name} (line {line}): {count} loops of {per_instantiation * LOOPS[name]} vectorised with "
                  f"{width}-byte vectors{'' if ok else '  <- FAILED'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
