"""tools/lammps_run.py on a machine without the project's venv (a cluster node, the 16-core
machine of bench/mpi_scaling.py): LUBRICATED_LMP names the lmp binary and LUBRICATED_MPIEXEC the
launcher with its options; the runs then go through them."""
import lammps_run


def test_the_named_binary_and_launcher_make_the_command(monkeypatch):
    monkeypatch.setenv("LUBRICATED_LMP", "/opt/lammps/bin/lmp")
    monkeypatch.setenv("LUBRICATED_MPIEXEC", "mpirun -bind-to core")
    assert lammps_run.lmp_command(1) == ["/opt/lammps/bin/lmp"]
    assert lammps_run.lmp_command(4) == ["mpirun", "-bind-to", "core", "-n", "4", "/opt/lammps/bin/lmp"]
    monkeypatch.delenv("LUBRICATED_MPIEXEC")
    assert lammps_run.lmp_command(2) == ["mpiexec", "-n", "2", "/opt/lammps/bin/lmp"]


def test_a_two_rank_run_through_the_named_binary_and_launcher(monkeypatch, lmp):
    # The named binary: a wrapper that marks each start (one per rank), then runs the wheel's lmp.
    wrapper = lmp.dir / "lmp-elsewhere"
    wrapper.write_text(f'#!/bin/sh\necho started >> "{lmp.dir / "starts"}"\n'
                       f'exec "{lammps_run.lammps_package_dir() / "lmp"}" "$@"\n')
    wrapper.chmod(0o755)
    monkeypatch.setenv("LUBRICATED_LMP", str(wrapper))
    monkeypatch.setenv("LUBRICATED_MPIEXEC", f"{lammps_run.VENV / 'bin' / 'mpiexec'} -bind-to core")
    results = lmp("""plugin load ${plugin}
units si
atom_style sphere
comm_modify vel yes
region box block 0 0.01 0 0.01 0 0.01
create_box 1 box
create_atoms 1 single 0.004 0.005 0.005
create_atoms 1 single 0.006 0.005 0.005
set group all diameter 0.002 density 2500
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8
run 0
print "RESULT atoms $(atoms)"
""", nprocs=2)
    assert results["atoms"] == 2
    assert "on 2 procs" in lmp.log
    assert (lmp.dir / "starts").read_text().split() == ["started", "started"]
