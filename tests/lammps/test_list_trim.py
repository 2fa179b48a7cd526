"""The wet pair style trims its neighbor list after each build (pair_lubricated_springdashpot_list.cpp):
a wet model asks LAMMPS for a list with per-type cutoffs (2 R_max + the film's reach + skin),
and drops in place the entries with r >= r_i + r_j + reach + skin, which no film or contact can
reach before the next build (each atom stays within skin / 2 of where the build found it).

The beds: the random polydisperse packings of tests/lammps/test_dense_packings.py (300 spheres,
radii log-uniform 0.1-1 mm, 1:10, periodic), where the per-type cutoff lists each small sphere's
every neighbour within 2 mm: *loose61* (solid fraction 0.61, the films) and *preloaded* (0.70,
sustained contacts, with friction: their elongations must follow the trimmed list across builds;
with rolling resistance they take the general loop), loose61 also with a grid (one reach for
all) and with two types (half the spheres each: wet pairs of unlike reach, dry pairs between),
random velocities of rms 0.3 m/s (from a hash of the atom ID: the same on any number of ranks) so
that the skin of 0.02 mm is crossed every few tens of steps, e_d = 0.9, N_c = 8, mu_f = 1e-3 Pa s,
eps_al = 0.1 (reach 0.05 mm for the largest pair), dt = 1e-6 s, 400 steps.

`trim no` keeps LAMMPS's list: the two runs select the same pairs in the same order (one piece of
pass 1: under pairs_per_piece entries per rank), so they agree to the bit, with 5 or more builds
and the trimmed list under half as long (measured: 3.0 against 20.2 neighbours per sphere, 3.9
against 23.3). Caught: a trim without the skin (a film lost), the history laid onto the list
before the trim (friction), a trim of the list compute pair/local shares (its sum over its
pairs), a restart file that forgets `trim no`.
"""
import pytest

import dense_packings as dp
import dense_scenes

SKIN = 2.0e-5
STEPS = 400
MIXED = "mixed"
MIXED_TYPES = """group odd id 1:300:2
set group odd type 2
pair_coeff 1 1 0.9 ncontact 8 viscosity 1e-3 activation 0.1
pair_coeff 2 2 0.8 ncontact 8 viscosity 1e-3 activation 0.05
pair_coeff 1 2 0.9 ncontact 8
"""
CASES = {
    "loose61 wet": ("loose61", "viscosity 1e-3 activation 0.1"),
    # a grid: one reach for every pair (0.75 dx, eps_al <= 1 for the two smallest spheres)
    "loose61 wet grid": ("loose61", "viscosity 1e-3 grid 5e-5"),
    # two types, half the spheres each: wet pairs of unlike reach and dry pairs between them
    # (their entries trimmed to r_i + r_j + skin)
    "loose61 mixed": ("loose61", MIXED),
    "preloaded wet friction": ("preloaded", "viscosity 1e-3 activation 0.1 friction 0.3"),
    # rolling resistance: the frictional contacts through the general loop (not vectorised)
    "preloaded wet friction rolling": ("preloaded", "viscosity 1e-3 activation 0.1 friction 0.3 rolling 0.1"),
}
DATA = {"loose61": "p61", "preloaded": "p70"}


def scene(packing, coefficients, trim, extra=""):
    sample = "".join(f'print "RESULT s{k} $(x[{k}]:%.17g) $(y[{k}]:%.17g) $(z[{k}]:%.17g) $(vx[{k}]:%.17g) '
                     f'$(vy[{k}]:%.17g) $(vz[{k}]:%.17g) $(v_wx[{k}]:%.17g)"\n' for k in range(1, 301, 23))
    data = f"{dp.pinned(DATA[packing])} extra/atom/types 1" if coefficients == MIXED else dp.pinned(DATA[packing])
    pair_coeff = MIXED_TYPES if coefficients == MIXED else f"pair_coeff * * 0.9 ncontact 8 {coefficients}\n"
    return dp.HEADER.format(boundary="p p p", data=data) + f"""{dense_scenes.hashed_velocities(0.3)}
pair_style lubricated/springdashpot trim {trim}
{pair_coeff}neighbor {SKIN!r} bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 1e-6
compute rot all erotate/sphere
compute spin all property/atom omegax
variable wx atom c_spin
compute pairs all pair lubricated/springdashpot
{extra}
thermo_style custom step atoms ke c_rot pe c_pairs[1] c_pairs[2]
thermo_modify lost error norm no
thermo 100
run {STEPS}
print "RESULT final $(ke:%.17g) $(c_rot:%.17g) $(pe:%.17g) $(c_pairs[1]) $(c_pairs[2]) $(atoms)"
""" + sample


def neighbours(log):
    """LAMMPS's `Ave neighs/atom` and `Neighbor list builds` of the run."""
    ave = [float(line.split("=")[1]) for line in log.splitlines() if line.startswith("Ave neighs/atom")]
    builds = [int(line.split("=")[1]) for line in log.splitlines() if line.startswith("Neighbor list builds")]
    return ave[-1], builds[-1]


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("case", CASES)
def test_trimmed_list_gives_the_same_run(lmp, case, nprocs):
    packing, coefficients = CASES[case]
    trimmed = lmp(scene(packing, coefficients, "yes"), nprocs=nprocs)
    assert dense_scenes.ranks(lmp.log) == {nprocs}
    ave_trimmed, builds_trimmed = neighbours(lmp.log)
    kept = lmp(scene(packing, coefficients, "no"), nprocs=nprocs)
    ave_kept, builds_kept = neighbours(lmp.log)
    assert builds_trimmed == builds_kept >= 5
    assert ave_trimmed < 0.5 * ave_kept
    assert trimmed == kept


# compute pair/local asks for an occasional list with the pair style's cutoff, which LAMMPS makes
# a copy of the pair style's list (the same arrays): that list must stay as built.
SHARED = """compute dist all pair/local dist
compute dist_sum all reduce sum c_dist inputs local
variable dist_sum equal c_dist_sum
fix dist_every all ave/time 50 1 50 v_dist_sum
"""


@pytest.mark.parametrize("nprocs", [1, 2])
def test_a_shared_list_is_not_trimmed(lmp, nprocs):
    packing, coefficients = CASES["loose61 wet"]
    report = 'print "RESULT shared $(c_dist_sum:%.17g)"\n'
    shared = lmp(scene(packing, coefficients, "yes", SHARED) + report, nprocs=nprocs)
    ave_shared, _ = neighbours(lmp.log)
    kept = lmp(scene(packing, coefficients, "no", SHARED) + report, nprocs=nprocs)
    ave_kept, _ = neighbours(lmp.log)
    assert ave_shared == ave_kept
    assert shared == kept


@pytest.mark.parametrize("trim", ["yes", "no"])
def test_trim_setting_survives_a_restart_file(lmp, trim):
    """The setting is one of the pair style's restart settings (bit 2 of its flags): a run read
    from the restart file keeps or trims its list as the run that wrote it."""
    packing, coefficients = CASES["loose61 wet"]
    lmp(scene(packing, coefficients, trim).replace(f"run {STEPS}", "run 0\nwrite_restart trim.restart"))
    ave_written, _ = neighbours(lmp.log)
    lmp(f"""plugin load ${{plugin}}
read_restart {lmp.dir}/trim.restart
neighbor {SKIN!r} bin
fix nve all nve/sphere
run 0
""")
    ave_read, _ = neighbours(lmp.log)
    assert ave_read == ave_written
    assert (ave_read < 5.0) == (trim == "yes")
