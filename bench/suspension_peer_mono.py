"""The coupled film solve against lubricateU/poly where the peer's films are pairwise: equal radii.

    .venv/bin/python bench/suspension_peer_mono.py            # phi 0.40 0.45 0.50, about 20 min
    .venv/bin/python bench/suspension_peer_mono.py --quick    # phi 0.45, squeeze films, 1 min
    .venv/bin/python bench/suspension_peer_mono.py --gtc 2.5e-4 --peer-steps 2e-4 1e-4 \
        --plugin-nc 1 2 4 8 --section suspension-peer-mono-stiff                   # stiffer contacts

bench/suspension_peer.py shears bidisperse packings (radii a and 1.4 a). There lubricateU/poly's
film forces are not pairwise (bench/peer_pair_check.py: a lone pair of unequal spheres at the
saturation gap is pushed through the fluid by a net force about 100 times its Stokes drag at the
shear velocity), its contacts keep compressing through the run and its conjugate gradients
slow down, so that comparison measures the peer's defect as much as the model. With equal
radii the defect vanishes. This bench repeats that comparison on monodisperse packings (radius
a, everything else as bench/suspension_peer.py: St 1e-3, mu_c 0.5, gdot t_c 1e-3, e_d 0.5, the
same contacts and cutoffs), for two sets of films:

  squeeze  the plugin's squeeze film alone (shearfilm no) against the peer's leading 1/h
           squeeze term alone (flaglog 0): the same physics but for the plugin's film being
           twice the two-sphere Stokes value near contact and vanishing continuously at eps_al;
  full     the plugin's squeeze and shear films against the peer's with its log terms
           (flaglog 1): the peer adds the log part of the squeeze film and the pump term (the
           films' torque against the relative spin), which the plugin has not.

Arms: the plugin at N_c 8 and 16 (--plugin-nc), the peer at gdot dt 5e-4 and 2.5e-4 (--peer-steps; and at
twice the first with a short time-out); --gtc sets both engines' contact duration (gdot t_c,
default 1e-3; examples/suspension_shear uses 2.5e-4, where the contacts no longer set the
stress). The verdict lines give eta_s plugin / peer of the finest arms and the cost per unit
strain of the arms converged to 5 %. Output: the tables on stdout and section
suspension-peer-mono of --results (default bench/RESULTS.md, 'none' to skip). Scratch:
build/bench-suspension-peer-mono (wiped at the start).
"""
import argparse
import json
import pathlib
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import bench_common  # noqa: E402
import suspension_peer as peer  # noqa: E402

peer.RATIO = 1.0                    # every sphere of radius a (both types)
ENGINES = {"full": (peer.PLUGIN_ENGINE, peer.PEER_ENGINE),
           "squeeze": (peer.PLUGIN_ENGINE.replace("shearfilm yes", "shearfilm no"),
                       peer.PEER_ENGINE.replace("{eta} 1 {cin_global}", "{eta} 0 {cin_global}"))}


def arms(quick, peer_steps, plugin_nc=(8, 16)):
    """The plugin at the given N_c; the peer at the given gdot dt (the first only with quick)."""
    plugin = [("plugin", peer.GTC / peer.GDOT / c) for c in plugin_nc]
    return plugin + [("peer", g / peer.GDOT) for g in (peer_steps[:1] if quick else peer_steps)]


def run_films(films, work, phi, strain, args):
    """Every arm of one film set on the packing in work; the summarised rows."""
    peer.PLUGIN_ENGINE, peer.PEER_ENGINE = ENGINES[films]
    rows = []
    probe = [] if args.quick else [("peer", 2 * args.peer_steps[0] / peer.GDOT)]
    todo = arms(args.quick, args.peer_steps, args.plugin_nc) + probe
    for engine, dt in todo:
        timeout = args.probe_timeout if (engine, dt) in probe else args.timeout
        row = peer.shear(work, engine, dt, strain, args.friction, phi, timeout)
        rows.append(row)
        print(f"{films} phi {phi:.3f} {peer.label(row)}: "
              + (f"time-out {row['timeout']:.0f} s" if "timeout" in row else
                 f"eta_s {row['eta_s']:.3f} P {row['P']:.4g} {row['seconds']:.1f} s"), flush=True)
    return peer.summarise(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="phi 0.45, squeeze films, fewer arms")
    parser.add_argument("--phis", type=float, nargs="+", default=None)
    parser.add_argument("--films", nargs="+", default=None, choices=sorted(ENGINES))
    parser.add_argument("--n", type=int, default=200)
    parser.add_argument("--strain", type=float, default=None, help="default 1 (0.5 with --quick)")
    parser.add_argument("--friction", type=float, default=0.5)
    parser.add_argument("--gtc", type=float, default=peer.GTC,
                        help="gdot t_c of both engines' contacts (default 1e-3)")
    parser.add_argument("--peer-steps", type=float, nargs="+", default=[5e-4, 2.5e-4],
                        help="the peer's gdot dt arms (plus one at twice the first with a short time-out)")
    parser.add_argument("--timeout", type=float, default=900.0)
    parser.add_argument("--probe-timeout", type=float, default=120.0)
    parser.add_argument("--seed", type=int, default=4928)
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-suspension-peer-mono"))
    parser.add_argument("--results", default=str(bench_common.RESULTS))
    parser.add_argument("--section", default="suspension-peer-mono", help="the section of --results written")
    parser.add_argument("--plugin-nc", type=float, nargs="+", default=[8, 16], help="the plugin's arms (N_c)")
    args = parser.parse_args()
    peer.GTC = args.gtc
    phis = args.phis or ([0.45] if args.quick else [0.40, 0.45, 0.50])
    films_sets = args.films or (["squeeze"] if args.quick else ["squeeze", "full"])
    strain = args.strain or (0.5 if args.quick else 1.0)
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    results = {f: [] for f in films_sets}
    for phi in phis:
        base = out / f"phi{phi}"
        base.mkdir(parents=True)
        measured = peer.make_packing(base, args.n, phi, args.seed)
        (base / "phi.json").write_text(json.dumps(measured))
        for films in films_sets:
            work = base / films
            work.mkdir()
            shutil.copy(base / "pack.data", work / "pack.data")
            results[films].append((measured, run_films(films, work, measured, strain, args)))
    lines = ["# Dense suspension, equal radii: the coupled film solve against lubricateU/poly "
             "(bench/suspension_peer_mono.py)", "",
             f"{args.n} spheres of one radius, St {peer.ST:g}, mu_c {args.friction}, gdot t_c {peer.GTC:g}, "
             f"e_d {peer.E_D}; one packing per phi, sheared from rest by both engines to strain {strain:g}, "
             f"stress averaged over the second half; one rank; LAMMPS {bench_common.lammps_version()}. "
             "Columns as in bench/suspension_peer.py.", ""]
    for films in films_sets:
        lines += [f"## films: {films}", ""] + peer.table(results[films]) + [""] + peer.verdict(results[films]) + [""]
    text = "\n".join(lines)
    print(text)
    if args.results != "none":
        bench_common.write_section(args.results, args.section, text)


if __name__ == "__main__":
    main()
