/* -*- c++ -*- ----------------------------------------------------------
   The unit styles this plugin supports. Every force it computes is a mass times an
   acceleration (contact: m_e (g2 - 2 g1 + g0) / dt^2; film and drag: a viscosity times a
   length times a velocity) and every energy a mass times a velocity squared, with no
   conversion factor: right where LAMMPS's force->ftm2v and force->mvv2e are 1 (lj, si, cgs,
   micro, nano), wrong by those factors elsewhere (real, metal, electron), where the viscosity
   would also need units LAMMPS does not define. Those are refused with an ERROR.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_UNIT_STYLE_H
#define LMP_LUBRICATED_UNIT_STYLE_H

#include "error.h"
#include "force.h"
#include "lammps.h"
#include "update.h"

namespace LAMMPS_NS {

inline void require_supported_units(LAMMPS *lmp, const char *style)
{
  if (lmp->force->ftm2v == 1.0 && lmp->force->mvv2e == 1.0) return;
  lmp->error->all(FLERR,
                  "{} does not support units {} (supported: lj, si, cgs, micro, nano, where force = mass * "
                  "acceleration and energy = mass * velocity^2; {} has ftm2v = {} and mvv2e = {})",
                  style, lmp->update->unit_style, lmp->update->unit_style, lmp->force->ftm2v, lmp->force->mvv2e);
}

}    // namespace LAMMPS_NS

#endif
