"""The vectorised loops of frictional contacts (vector_pairs.h friction_contacts, sustained, and
friction_events, those that start or end within a step) give the general loop's results
(`pair_style lubricated/springdashpot vector no`) on dense frictional beds, dry and wet, with the
film budget binding (`limit atom`, strong films) and without it (`limit pair`), with and without
the shear film, with a fixed activation and a grid, on 1 and 2 ranks. So do the frictionless loops (contact_or_film, contact_exits and contact_events: contacts
that start or end within a step, 0.07-0.3 per sphere and step here) on the same beds without
friction. The contacts that start or end wait in a list over the chunks of pairs: larger beds
(1372 spheres) fill it within a step, beds of two types with a model per type pair make it run
when another model's pairs come (both checked to happen, and the tests to fail where the list
does not run at the end of a step or keeps one model's pairs for another's).

The bed: 256 spheres of radii 0.99-1.0 mm (from a hash of the atom ID) on a periodic fcc lattice
compressed to 0.995 of 2 mm, so that most neighbours overlap (sustained contacts) and some pairs
sit apart inside the film, with random velocities (rms 0.1 m/s) and spins (up to 100 rad/s, slips
of 0.1 m/s: contacts stick and slide). Two runs of 60 steps (the second run's set-up continues
the first): 15 contact durations.

Tolerance: relative 1e-7 on positions, velocities, spins, energies and pressure after 120 steps.
The loops differ in rounding only (fused multiply-adds, the inline logarithm and exponential:
the first step agrees to the last digit), but a dense bed amplifies rounding: the general loop
itself, on 1 and on 2 ranks (which only reorder sums), differs by up to 4e-9 after these 120
steps (by 1e-8 after 300), and the two loops by as much. Leaving out the sliding reset, the
shear film or the film of the pairs apart in the vectorised loop makes differences of 2e-3 to
1; leaving out the rotation of the elongation into the tangent plane, whose effect over one step
is small here, 1e-7 to 4e-6 (caught, barely: tests/kernel/test_vector_friction.cpp checks each
pair against the whole contact to 1e-11).
"""
import pytest

import dense_scenes

R = 1.0e-3
COMPRESSION = 0.995    # lattice spacing / 2R

CASES = {
    "dry": "friction 0.3",
    # strong films (mu_f 0.3 Pa s): the budget binds; the shear film with a grid's eps_al
    "wet grid": "viscosity 0.3 grid 1.25e-4 friction 0.3",
    "wet activation shearfilm no": "viscosity 0.3 activation 0.1 friction 0.3 shearfilm no",
    # without the budget, films that strong make this bed unstable (test_dense_beds.py: the general
    # loop on 1 and 2 ranks differs by 100 % after 120 steps): a weak film, the shear film with a
    # fixed eps_al
    "wet activation limit pair": "viscosity 1e-3 activation 0.1 friction 0.3",
}

# Without friction: the sustained contacts, the films and the contacts that start or end.
FRICTIONLESS = {
    "dry": "",
    "wet grid": "viscosity 0.3 grid 1.25e-4",
    "wet activation limit pair": "viscosity 1e-3 activation 0.1",
}

# Half the spheres of type 2, a model per type pair: the pairs of each model are grouped (and the
# loops of contacts that start or end run before another model's pairs join them).
MIXED = "pair_coeff 1 1 0.9 ncontact 8 {0}\npair_coeff 1 2 0.8 ncontact 6 {0}\npair_coeff 2 2 0.7 ncontact 10 {0}"

# A hash of the atom ID in [0, 1) (the same on any number of ranks, unlike random()).
HASH = "(v_h{k}-floor(v_h{k}))"


def bed(coefficients, limit, vector, cells=4, mixed=False):
    a = 2.0 * R * COMPRESSION * 2 ** 0.5
    hashes = "\n".join(f"variable h{k} atom sin(id*{12.9898 + k}+{k})*43758.5453" for k in range(7))
    u = [HASH.format(k=k) for k in range(7)]
    return dense_scenes.HEADER + f"""lattice fcc {a!r}
region box block 0 {cells} 0 {cells} 0 {cells}
create_box {2 if mixed else 1} box
create_atoms 1 box
{"group odd id 1:100000:2" + chr(10) + "set group odd type 2" if mixed else ""}
{hashes}
variable d atom {2 * R!r}*(0.99+0.01*{u[0]})
set group all diameter v_d
set group all density 2500
variable vx atom 0.1*(2*{u[1]}-1)
variable vy atom 0.1*(2*{u[2]}-1)
variable vz atom 0.1*(2*{u[3]}-1)
velocity all set v_vx v_vy v_vz units box
variable wx atom 100*(2*{u[4]}-1)
variable wy atom 100*(2*{u[5]}-1)
variable wz atom 100*(2*{u[6]}-1)
set group all omega v_wx v_wy v_wz
pair_style lubricated/springdashpot {'' if vector else 'vector no'} limit {limit}
{MIXED.format(coefficients) if mixed else "pair_coeff * * 0.9 ncontact 8 " + coefficients}
neighbor {0.2 * R!r} bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 1e-5
compute rot all erotate/sphere
compute spin all property/atom omegax omegay omegaz
variable sx atom c_spin[1]
variable sy atom c_spin[2]
variable sz atom c_spin[3]
compute contacts all contact/atom
compute mean_contacts all reduce ave c_contacts
thermo_style custom step atoms ke c_rot pe press c_mean_contacts
thermo_modify lost error norm no
thermo 50
run 60
run 60
print "RESULT energies $(ke:%.17g) $(c_rot:%.17g) $(pe:%.17g) $(press:%.17g) $(c_mean_contacts:%.17g)"
""" + "".join(f'print "RESULT s{k} $(x[{k}]:%.17g) $(y[{k}]:%.17g) $(z[{k}]:%.17g) $(vx[{k}]:%.17g) '
              f'$(vy[{k}]:%.17g) $(vz[{k}]:%.17g) $(v_sx[{k}]:%.17g) $(v_sy[{k}]:%.17g) '
              f'$(v_sz[{k}]:%.17g)"\n' for k in range(1, 257, 15))


# Each case's coefficients, the log line that says its vectorised loops run and the lattice's
# cells per edge: 4 (256 spheres), 7 (1372) where more contacts start or end in a step than the
# loops of those contacts take at once (256: they then run more than once per step).
# Each sphere's position, velocity and spin components: rounding differs relative to each
# quantity's scale (R, the imposed 0.1 m/s and 100 rad/s), not to a component that happens to be
# near zero (a velocity component of 4e-7 m/s differed by 4e-14 once the shared film terms
# changed their rounding): 1e-8 of the scale, beside the relative 1e-7.
SCALES = [R] * 3 + [0.1] * 3 + [100.0] * 3

FRICTION_LOG = "pairs in sustained frictional contact take a vectorised loop"
FRICTIONLESS_LOG = "contacts that start or end within a step (without legendre), take vectorised loops"
LOOPS = {**{case: (c, FRICTION_LOG, 4) for case, c in CASES.items()},
         **{f"{case} frictionless": (c, FRICTIONLESS_LOG, 4) for case, c in FRICTIONLESS.items()},
         "dry 1372 spheres": (CASES["dry"], FRICTION_LOG, 7),
         "dry frictionless 1372 spheres": (FRICTIONLESS["dry"], FRICTIONLESS_LOG, 7),
         "wet grid mixed": (CASES["wet grid"], FRICTION_LOG, 7),
         "wet grid frictionless mixed": (FRICTIONLESS["wet grid"], FRICTIONLESS_LOG, 7)}


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("case", LOOPS)
def test_vectorised_loops_agree_with_the_general_loop(lmp, case, nprocs):
    """The bed with the vectorised loops and with the general loop alone: the same results to
    rounding."""
    coefficients, logged, cells = LOOPS[case]
    limit = "pair" if "limit pair" in case else "atom"
    mixed = "mixed" in case
    vectorised = lmp(bed(coefficients, limit, True, cells, mixed), nprocs=nprocs)
    assert logged in lmp.log
    assert dense_scenes.ranks(lmp.log) == {nprocs}
    general = lmp(bed(coefficients, limit, False, cells, mixed), nprocs=nprocs)
    assert "vectorised" not in lmp.log
    ke, rot, pe, press, contacts = vectorised["energies"]
    # A dense bed: most spheres in several sustained contacts throughout; they spin (imposed
    # spins, which friction changes).
    assert contacts > 3.0 and rot > 0.0 and pe > 0.0
    assert vectorised.keys() == general.keys()
    assert vectorised["energies"] == pytest.approx(general["energies"], rel=1e-7, abs=1e-15)
    for key in vectorised.keys() - {"energies"}:
        for got, want, scale in zip(vectorised[key], general[key], SCALES):
            assert got == pytest.approx(want, rel=1e-7, abs=1e-8 * scale), key
