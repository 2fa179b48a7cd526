"""Helpers shared by the bed benchmarks (settling_bed.py, independent_beds.py).

Log parsing (loop time, timing breakdown, neighbour statistics, list cutoff, memory), the
built-in Hooke coefficients that match the plugin's spring-dashpot, plain-words physics
flags, and write_section, which puts a bench's report into its section of bench/RESULTS.md.
No LAMMPS import: the benches run the `lmp` binary through tools/lammps_run.py.
"""
import math
import pathlib
import re

LOOP = re.compile(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")
SECTIONS = ("Pair", "Neigh", "Comm", "Output", "Modify", "Other")


def hooke_coefficients(radius, rho, e_d, n_c, dt):
    """LAMMPS gran/hooke(/history) constants with the plugin's normal stiffness and damping.

    The plugin: k = m_e (pi^2 + ln^2 e_d) / t_c^2 and c = -2 ln(e_d) m_e / t_c with t_c = N_c dt
    (doc/model.rst); gran/hooke applies its damping per unit reduced mass, so gamma_n = c / m_e
    is the same for every pair, while Kn needs m_e: m/2 between two spheres of this radius, m at
    a wall. With friction the plugin's tangential spring-dashpot has e_t = e_d and the mass
    2/7 m_e (solid spheres): Kt = 2/7 Kn, gamma_t = 2/7 gamma_n.
    """
    mass = rho * 4.0 / 3.0 * math.pi * radius ** 3
    t_c = n_c * dt
    kappa = (math.pi ** 2 + math.log(e_d) ** 2) / t_c ** 2          # k / m_e
    gamma_n = -2.0 * math.log(e_d) / t_c                              # c / m_e
    kn_pair, kn_wall = 0.5 * mass * kappa, mass * kappa
    return dict(kn_pair=kn_pair, kn_wall=kn_wall, gamma_n=gamma_n, kt_pair=2.0 / 7.0 * kn_pair,
                kt_wall=2.0 / 7.0 * kn_wall, gamma_t=2.0 / 7.0 * gamma_n)


def parse_log(log, all_runs=False):
    """Timing of a LAMMPS log: the first run, or with all_runs the sum of every run in log
    (the chunks of `run N every M`). Returns seconds, steps, atoms, ns per particle-step,
    section times and shares of the loop (Pair, Neigh, ...), dangerous builds, and where the
    log has them the last neighbour statistics (half-list entries per atom), the master list
    cutoff and the first 'Per MPI rank memory' figure (Mbytes, avg)."""
    loops = list(LOOP.finditer(log))
    if not loops:
        raise ValueError("no 'Loop time' line in the log")
    used = loops if all_runs else loops[:1]
    seconds = sum(float(m.group(1)) for m in used)
    steps = sum(int(m.group(3)) for m in used)
    atoms = int(used[0].group(4))
    times = dict.fromkeys(SECTIONS, 0.0)
    found = set()
    for k, m in enumerate(used):
        end = loops[k + 1].start() if k + 1 < len(loops) else len(log)
        body = log[m.end():end]
        for section in SECTIONS:
            row = re.search(rf"^{section}\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]+)\s*\|", body, re.M)
            # LIGGGHTS 3.8 (the LAMMPS of 2013) writes "Pair  time (%) = 0.47 (85.3)", "Outpt"
            old = re.search(rf"^{section[:4] if section != 'Output' else 'Outpt'}\s+time \(%\) = ([0-9.eE+-]+)",
                            body, re.M)
            if row or old:
                times[section] += float(row.group(2) if row else old.group(1))    # avg time over ranks
                found.add(section)
    shares = {s: (times[s] / seconds if s in found and seconds > 0 else float("nan")) for s in SECTIONS}
    dangerous = [int(d) for d in re.findall(r"Dangerous builds = (\d+)", log)]
    neighs = re.findall(r"Ave neighs/atom = ([0-9.eE+-]+)", log)
    cutoff = re.search(r"master list distance cutoff = ([0-9.eE+-]+)", log)
    memory = (re.search(r"Per MPI rank memory allocation \(min/avg/max\) = ([0-9.eE+-]+) \| ([0-9.eE+-]+)", log)
              or re.search(r"Memory usage per processor = ()([0-9.eE+-]+) Mbytes", log))         # LIGGGHTS
    rss = re.search(r"Maximum resident set size:\s*([0-9.eE+-]+)\s*Mbyte", log)
    ns = seconds / (steps * atoms) * 1e9 if steps else float("nan")
    return dict(seconds=seconds, steps=steps, atoms=atoms, ns=ns,
                times=times, shares=shares, dangerous=sum(dangerous) if dangerous else -1,
                neighs=float(neighs[-1]) if neighs else float("nan"),
                cutoff=float(cutoff.group(1)) if cutoff else float("nan"),
                memory=float(memory.group(2)) if memory else float("nan"),
                rss=float(rss.group(1)) if rss else float("nan"))


def physics_flags(check, limit=0.2):
    """Plain-words warnings about the final state of a run (overlaps in units of R)."""
    flags = []
    if check["sunk"] > 0:
        flags.append(f"{int(check['sunk'])} sphere centres below z = R/2 (through the floor)")
    if check["wall_overlap"] > limit:
        flags.append(f"wall overlap {check['wall_overlap']:.3f} R")
    if check["pair_overlap"] > limit:
        flags.append(f"pair overlap {check['pair_overlap']:.3f} R")
    return flags


def lammps_version():
    try:
        import importlib.metadata
        return importlib.metadata.version("lammps")
    except Exception:                    # noqa: BLE001 - the version is only a label
        return "(unknown)"


# The run settings every bed bench gives every style (gravity, integrator, neighbour list, dt).
SETTINGS = """fix nve all nve/sphere
fix weight all gravity {g} vector 0 0 -1
neighbor {skin} bin
neigh_modify delay 0 every 1 check yes
timestep {dt}
"""


RESULTS = pathlib.Path(__file__).resolve().parent / "RESULTS.md"


def _demoted(text):
    """The markdown text with every heading two levels down: a report's title sits under the
    section's own heading (##) in bench/RESULTS.md."""
    lines, fenced = [], False
    for line in text.strip("\n").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        lines.append("##" + line if line.startswith("#") and not fenced else line)
    return "\n".join(lines)


def write_section(path, name, text):
    """Put a bench's report into its own section of the markdown file path (bench/RESULTS.md).

    The section lies between the lines `<!-- name begin -->` and `<!-- name end -->`; the text
    replaces what is there, its headings two levels down, and everything outside the markers
    (the file's introduction, notes written by hand, the other benches' sections) stays. A file
    without that section gets it at the end; a missing file is created."""
    path = pathlib.Path(path)
    begin, end = f"<!-- {name} begin -->", f"<!-- {name} end -->"
    section = f"{begin}\n{_demoted(text)}\n{end}"
    old = path.read_text() if path.exists() else ""
    pattern = re.compile(re.escape(begin) + r".*?" + re.escape(end), re.S)
    if pattern.search(old):
        new = pattern.sub(lambda _: section, old, count=1)
    else:
        new = (old.rstrip("\n") + "\n\n" if old.strip() else "") + section + "\n"
    path.write_text(new)
    return path


if __name__ == "__main__":
    # bench_common.py NAME REPORT [RESULTS]: a report written elsewhere (a device machine's run)
    # becomes section NAME of bench/RESULTS.md (or of RESULTS).
    import sys
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: bench_common.py NAME REPORT [RESULTS]")
    target = sys.argv[3] if len(sys.argv) == 4 else RESULTS
    print("wrote", write_section(target, sys.argv[1], pathlib.Path(sys.argv[2]).read_text()))
