/* ----------------------------------------------------------------------
   memory_parts: where LAMMPS's "Per MPI rank memory allocation" goes, part by part (issue 19).
   Runs an input file with the plugin loaded (the input's `plugin load`), then prints the
   memory_usage() of each part that LAMMPS sums for that figure (atom, neighbor, comm, update,
   force: the pair style; modify: each fix) in MB per 1000 atoms, one rank. Built by CMake
   (build/memory_parts) where liblammps.so is found; bench/RESULTS.md has its figures.

       build/memory_parts in.file [-var name value ...]
------------------------------------------------------------------------- */

#include "atom.h"
#include "comm.h"
#include "fix.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <mpi.h>

#include <cstdio>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

int main(int argc, char **argv)
{
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s in.file [-var name value ...]\n", argv[0]);
    return 1;
  }
  MPI_Init(&argc, &argv);
  std::vector<char *> args = {argv[0], const_cast<char *>("-log"), const_cast<char *>("log.memory_parts"),
                              const_cast<char *>("-screen"), const_cast<char *>("none")};
  for (int k = 2; k < argc; k++)
    args.push_back(argv[k]);
  auto *lmp = new LAMMPS(static_cast<int>(args.size()), args.data(), MPI_COMM_WORLD);
  lmp->input->file(argv[1]);

  const double per = 1.0e3 / (1024.0 * 1024.0) / static_cast<double>(lmp->atom->natoms);
  double total = 0.0;
  auto part = [&](const std::string &name, double bytes) {
    std::printf("PART %-40s %8.4f MB/1000 atoms %14.0f bytes\n", name.c_str(), bytes * per, bytes);
    total += bytes;
  };
  part("atom", lmp->atom->memory_usage());
  part("neighbor", lmp->neighbor->memory_usage());
  part("comm", lmp->comm->memory_usage());
  part("update", lmp->update->memory_usage());
  const double pair = lmp->force->pair ? lmp->force->pair->memory_usage() : 0.0;
  part(std::string("pair ") + (lmp->force->pair_style ? lmp->force->pair_style : "none"), pair);
  part("force (other than pair)", lmp->force->memory_usage() - pair);
  double fixes = 0.0;
  for (Fix *fix : lmp->modify->get_fix_list()) {
    part(std::string("fix ") + fix->id + " " + fix->style, fix->memory_usage());
    fixes += fix->memory_usage();
  }
  part("modify (other than fixes)", lmp->modify->memory_usage() - fixes);
  std::printf("TOTAL %8.4f MB/1000 atoms (%g atoms)\n", total * per, static_cast<double>(lmp->atom->natoms));
  std::printf("NMAX %d\n", lmp->atom->nmax);
  delete lmp;
  MPI_Finalize();
  return 0;
}
