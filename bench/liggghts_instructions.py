"""Where LIGGGHTS's time goes on the independent random bed (issue 19): callgrind instruction
counts (Ir) per particle-step of `model lubricated` wet against `model hooke/stiffness`, both
with LIGGGHTS's tangential history and friction 0.3, split by what executes them.

    .venv/bin/python bench/liggghts_instructions.py [--bed build/bench-beds/bed2000] [--steps 300]
        [--library before=/tmp/old/liblubricated_liggghts.so --library after=build/liblubricated_liggghts.so]

The bed and inputs are bench/independent_beds.py's (`--liggghts`): its cached settled bed
(BED/settled.data; `independent_beds.py --sizes 2000 --states settled --repeats 1` makes it)
and its LIGGGHTS input, settled and active, with --steps steps (active: velocities imposed
every 100 steps). Only LIGGGHTS's time-step loop is counted (Verlet::run, not the set-ups).
Instruction counts do not depend on the machine's load (one run per case is exact); they count
instructions, not cycles. For line-level detail build with -DCMAKE_CXX_FLAGS=-g and run
callgrind_annotate on the files left in --out.
"""
import argparse
import os
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import independent_beds as beds  # noqa: E402
import liggghts_run  # noqa: E402

MODELS = {"hooke/stiffness": ("hooke/stiffness", 0), "lubricated wet": ("lubricated", 1)}
# What executes the instructions, from callgrind_annotate's file:function (first match wins).
PARTS = [
    ("tangential history (LIGGGHTS)", r"tangential_model|TangentialModel"),
    ("surface model (LIGGGHTS)", r"surface_model|SurfaceModel|0x000000000041dd40"),
    ("model lubricated: close-pair loop", r"close_pairs\.cpp|close_loop|ClosePairs"),
    ("model lubricated: budget, step velocity", r"FixLubricated"),
    ("model lubricated: contacts and close pairs", r"src/lubricated/|src/liggghts/|NormalModel<42>|e_log\.c|"
                                                   r"w_log_template|lubricated::"),
    ("normal model hooke/stiffness", r"NormalModel<1>"),
    ("pair loop (LIGGGHTS)", r"pair_gran_base|contact_models\.h|contact_interface|Granular<|memset|PairGran"),
    ("neighbour lists", r"Neighbor|NeighList|neigh_"),
    ("integration, gravity", r"FixNVESphere|FixGravity"),
    ("communication", r"Comm|AtomVec|pack|unpack"),
]


def profile(library, model, wet, state, steps, data, out):
    fmt = dict(beds.hooke_coefficients(beds.R, beds.RHO, beds.E_DRY, beds.NC, beds.DT), half_r_min=0.5 * beds.R_MIN,
               skin=beds.SKIN, e=beds.E_DRY, mu=beds.MU_C, nc=beds.NC, g=beds.G, dt=beds.DT, model=model,
               wet=beds.LIGGGHTS_WET if wet else "", steps=steps,
               thermo=beds.KICK_EVERY if state == "active" else steps,
               drive=beds.ACTIVE_DRIVE if state == "active" else "",
               chunks=beds.ACTIVE_CHUNKS if state == "active" else "")
    script = beds.LIGGGHTS.format(**fmt).replace("../settled_liggghts.data", str(data))
    tag = f"{state}.{model.replace('/', '_')}"
    (out / f"in.{tag}").write_text(script)
    profile_file = out / f"callgrind.{tag}"
    env = dict(os.environ, OMP_NUM_THREADS="1", LD_PRELOAD=str(library))
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={profile_file}", "--collect-atstart=no",
                    "--toggle-collect=LAMMPS_NS::Verlet::run(int)", liggghts_run.LIGGGHTS, "-in", f"in.{tag}",
                    "-log", f"in.{tag}.log", "-screen", "none", "-echo", "none"],
                   cwd=out, env=env, check=True, capture_output=True)
    text = subprocess.run(["callgrind_annotate", "--threshold=100", "--auto=no", str(profile_file)], check=True,
                          capture_output=True, text=True).stdout
    parts = dict.fromkeys([name for name, _ in PARTS] + ["other"], 0)
    total = 0
    for line in text.splitlines():
        match = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+(.*)$", line)
        if not match:
            continue
        count, where = int(match.group(1).replace(",", "")), match.group(2)
        if "PROGRAM TOTALS" in where:
            total = count
            continue
        parts[next((name for name, pattern in PARTS if re.search(pattern, where)), "other")] += count
    natoms = int(re.search(r"(\d+) atoms", data.read_text()[:400]).group(1))
    scale = 1.0 / (natoms * steps)
    return total * scale, {name: count * scale for name, count in parts.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bed", default=str(ROOT / "build/bench-beds/bed2000"))
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--library", action="append", default=[],
                        help="label=path of liblubricated_liggghts.so (default: this build's)")
    parser.add_argument("--out", default=str(ROOT / "build/bench-liggghts-instructions"))
    args = parser.parse_args()
    bed = pathlib.Path(args.bed)
    if not (bed / "settled.data").exists():
        sys.exit(f"no bed in {bed}: run bench/independent_beds.py --sizes 2000 --states settled --repeats 1 first")
    data = pathlib.Path(args.out).resolve() / "settled_liggghts.data"
    data.parent.mkdir(parents=True, exist_ok=True)
    beds.liggghts_data(bed / "settled.data", data)
    libraries = [item.split("=", 1) for item in args.library] or [["this build", str(liggghts_run.LIBRARY)]]
    for state in ("settled", "active"):
        reference = None
        for label, library in libraries:
            out = pathlib.Path(args.out).resolve() / label.replace(" ", "_")
            shutil.rmtree(out / state, ignore_errors=True)
            (out / state).mkdir(parents=True)
            for name, (model, wet) in MODELS.items():
                if name == "hooke/stiffness" and reference is not None:
                    continue    # the library does not change LIGGGHTS's own model
                total, parts = profile(pathlib.Path(library).resolve(), model, wet, state, args.steps, data,
                                       out / state)
                if name == "hooke/stiffness":
                    reference = total
                print(f"\n{state}, {name} ({label}): {total:.0f} Ir per particle-step, "
                      f"{total / reference:.2f}x hooke/stiffness")
                for part, value in sorted(parts.items(), key=lambda item: -item[1]):
                    if value >= 0.5:
                        print(f"  {value:7.0f}  {part}")


if __name__ == "__main__":
    main()
