"""A small dense suspension in simple shear for the tests of the coupled film solve (issue 45):
the packing of examples/suspension_shear (bidisperse, radii a and 1.4 a, rho_p = rho_f, inserted
at solid fraction 0.2, compressed dry to phi, relaxed in fluid at rest), written once to a data
file, then sheared from rest for a few hundred steps with the example's physics: `limit
implicit`, friction, `fix fluid/drag ... flow affine` with `fix_modify virial yes`,
`fix deform xy erate`, stress from `compute pressure NULL virial`.

packing() runs the example's own input up to its shear stage (so the scene follows the example)
and adds write_data. shear() reads that file and shears it; its knobs are the units of the run:
gdot, eta_f (through St = rho gdot a^2 / eta_f), rho and a (with scaled_data()), with the contact duration t_c =
gtc / gdot and dt = t_c / nc as in the example. It prints, with every digit,

    RESULT mean  <eta_s> <P / (eta_f gdot)> <mu>     (averaged over every step of the run)
    RESULT final <eta_s> <P / (eta_f gdot)> <mu>     (the last step)
    RESULT iterations <CG iterations per step, averaged>

and writes final.dump (id, x y z / a, v / (gdot a), f / (eta_f gdot a^2), sorted by id).
"""
import pathlib

import numpy as np

from suspension_packing import packing_script  # noqa: F401 (tools/: the example's packing)

PACKING = {"n": 80, "phi": 0.54, "St": 1e-3, "gtc": 1e-3, "nc": 16}


SHEAR = """plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
newton on
read_data {data}
variable a equal {a!r}
variable rho equal {rho!r}
variable gdot equal {gdot!r}
variable eta_f equal v_rho*v_gdot*v_a^2/{St!r}
variable tc equal {gtc!r}/v_gdot
set type 1 diameter $(2*v_a) density ${{rho}}
set type 2 diameter $(2.8*v_a) density ${{rho}}
velocity all set 0 0 0
set group all omega 0 0 0
neighbor $(0.3*v_a) bin
neigh_modify delay 0 every 1 check yes
timestep $(v_tc/{nc})
pair_style lubricated/springdashpot limit implicit tolerance {tol!r}
pair_coeff * * 0.5 tcontact ${{tc}} viscosity ${{eta_f}} activation 0.1 friction {mu_c}
fix nve all nve/sphere
fix shear all deform 1 xy erate ${{gdot}} remap v
fix drag all fluid/drag viscosity ${{eta_f}} density {rho_f!r} law stokes flow affine
fix_modify drag virial yes
compute stress all pressure NULL virial
compute solve all pair lubricated/springdashpot
variable unit equal v_eta_f*v_gdot
variable eta_s equal 1-c_stress[4]/v_unit
variable p equal c_stress/v_unit
variable mu equal -c_stress[4]/c_stress
variable iter equal c_solve[3]
fix mean all ave/time 1 {steps} {steps} v_eta_s v_p v_iter
thermo_style custom step ke v_eta_s v_p v_mu v_iter
thermo_modify norm no
thermo {thermo}
run {steps}
print "RESULT mean $(f_mean[1]:%.17g) $(f_mean[2]:%.17g) $((f_mean[1]-1)/f_mean[2]:%.17g)"
print "RESULT final $(v_eta_s:%.17g) $(v_p:%.17g) $(v_mu:%.17g)"
print "RESULT iterations $(f_mean[3]:%.17g)"
variable xa atom (x-xlo)/v_a
variable ya atom (y-ylo)/v_a
variable za atom (z-zlo)/v_a
variable vunit equal v_gdot*v_a
variable funit equal v_eta_f*v_gdot*v_a^2
variable vxs atom vx/v_vunit
variable vys atom vy/v_vunit
variable vzs atom vz/v_vunit
variable fxs atom fx/v_funit
variable fys atom fy/v_funit
variable fzs atom fz/v_funit
write_dump all custom final.dump id v_xa v_ya v_za v_vxs v_vys v_vzs v_fxs v_fys v_fzs modify sort id format float %.17g
"""


def shear(data, gdot=1.0, St=1e-3, rho=1000.0, a=1e-4, steps=300, tol=1e-10, mu_c=0.5, rho_f=None, thermo=100):
    """The shear stage on the packing in `data` (for a != 1e-4 m: scaled_data(), same factor)."""
    return SHEAR.format(data=data, a=a, rho=rho, gdot=gdot, St=St, gtc=PACKING["gtc"],
                        nc=PACKING["nc"], tol=tol, mu_c=mu_c, steps=steps, thermo=thermo,
                        rho_f=rho if rho_f is None else rho_f)


def scaled_data(data, factor, out):
    """The data file `data` with its box and positions times `factor` (exactly, for a power of
    two), velocities dropped (the shear starts from rest), written to `out`."""
    scaled, section = [], None
    for line in pathlib.Path(data).read_text().splitlines():
        words = line.split()
        if line and not line[0].isspace() and len(words) <= 3 and not words[0][0].isdigit() and not words[0][0] == "-":
            section = words[0]
        if len(words) == 4 and words[2].endswith("lo"):
            line = f"{float(words[0]) * factor!r} {float(words[1]) * factor!r} {words[2]} {words[3]}"
        elif section == "Atoms" and len(words) == 10:
            xyz = [repr(float(w) * factor) for w in words[4:7]]
            line = " ".join(words[:4] + xyz + words[7:])
        elif section == "Velocities":
            break
        scaled.append(line)
    pathlib.Path(out).write_text("\n".join(scaled) + "\n")
    return out


def final_state(directory):
    """final.dump as an array, rows sorted by id: id, x/a, v/(gdot a), f/(eta_f gdot a^2)."""
    lines = (pathlib.Path(directory) / "final.dump").read_text().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    return np.array([[float(w) for w in line.split()] for line in lines[start:]])
