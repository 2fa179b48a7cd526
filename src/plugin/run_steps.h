/* -*- c++ -*- ----------------------------------------------------------
   Whether the run (or minimisation) being initialised takes steps: `run 0` and an init outside
   a run (write_data, write_restart) do not. ncontact's t_c is settled only by a run with steps
   (lubricated/coefficients.h settle_contact_time).
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_RUN_STEPS_H
#define LMP_LUBRICATED_RUN_STEPS_H

#include "update.h"

namespace LAMMPS_NS {

inline bool run_has_steps(const Update *update)
{
  return update->whichflag != 0 && update->nsteps > 0;
}

}    // namespace LAMMPS_NS

#endif
