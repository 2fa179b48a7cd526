# Two commands on a fresh Debian 12 machine:  make demo  and  make test.
VENV   := .venv
PY     := $(VENV)/bin/python
BUILD  := build
JOBS   ?= 2

.PHONY: all setup setup-liggghts build demo test test-kernel test-lammps test-liggghts bench format format-check \
        bench-liggghts report fluidized-bed rotating-drum liggghts-demo clean

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

test: setup-liggghts build format-check test-kernel test-lammps test-liggghts

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
# (bench/RESULTS.md and bench/SCALING.md hold the last figures).
bench: build
	$(PY) bench/settling_bed.py --out $(BUILD)/bench
	$(PY) bench/bed_scaling.py --out $(BUILD)/bed_scaling

# LIGGGHTS settling bed: model lubricated against model hooke/stiffness (bench/RESULTS_LIGGGHTS.md).
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

# The 2133-sphere fluidised bed on 2 MPI ranks: dumps and a solid-fraction profile.
fluidized-bed: build
	$(PY) examples/fluidized_bed/run_fluidized_bed.py --out $(BUILD)/fluidized_bed

# A dry and a wet rotating drum (fix wall/lubrication zcylinder shear): the dynamic angle of
# repose and rotating_drum.png (under a minute).
rotating-drum: build
	$(PY) examples/rotating_drum/run_rotating_drum.py --out $(BUILD)/rotating_drum

clean:
	rm -rf $(BUILD)
