// Registers `model lubricated` combined with LIGGGHTS's own tangential, cohesion and rolling
// models in the pair and wall style factories of a running LIGGGHTS (one template per
// combination, as LIGGGHTS's granular_styles.h does for its built-in models).
#pragma once

#include "liggghts/normal_model_lubricated.h"

#include "fix_wall_gran_base.h"
#include "liggghts/insert_stream_stub.h"
#include "pair_gran_base.h"
#undef FixInsertStream
#include "liggghts/pair_pass.h"

namespace lubricated {
namespace liggghts {

template <class Style>
LIGGGHTS::PairStyles::IGranularPairStyle *create_pair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, int64_t hash)
{
  return new PairPass<LIGGGHTS::ContactModels::ContactModel<Style>>(lmp, parent, hash);
}

template <class Style>
LIGGGHTS::Walls::IGranularWall *create_wall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *parent, int64_t hash)
{
  return new LIGGGHTS::Walls::Granular<LIGGGHTS::ContactModels::ContactModel<Style>>(lmp, parent, hash);
}

template <int TANGENTIAL, int COHESION, int ROLLING> void register_combination()
{
  using namespace LIGGGHTS::ContactModels;
  typedef GranStyle<LUBRICATED, TANGENTIAL, COHESION, ROLLING, SURFACE_DEFAULT> Style;
  LIGGGHTS::PairStyles::Factory::instance().addStyle("gran", Style::HASHCODE, &create_pair<Style>);
  LIGGGHTS::Walls::Factory::instance().addStyle("gran", Style::HASHCODE, &create_wall<Style>);
}

// One function per tangential model (separate translation units, built in parallel).
void register_tangential_off();
void register_tangential_no_history();
void register_tangential_history();

}    // namespace liggghts
}    // namespace lubricated
