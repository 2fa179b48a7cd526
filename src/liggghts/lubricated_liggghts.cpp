// liblubricated_liggghts.so: adds `model lubricated` to a stock LIGGGHTS 3.8.0 when loaded
// (LD_PRELOAD=.../liblubricated_liggghts.so liggghts -in ..., or the liggghts-lubricated
// launcher). Everything here runs from a static initialiser, after libliggghts.so's own.
#include "liggghts/register_lubricated.h"

namespace lubricated {
namespace liggghts {

namespace {
LIGGGHTS::ContactModels::ContactModelBase *last_pair_model = nullptr;
LIGGGHTS::ContactModels::NormalModel<LIGGGHTS::ContactModels::LUBRICATED> *last_normal_model = nullptr;
}    // namespace

void note_pair_contact_model(LIGGGHTS::ContactModels::ContactModelBase *model,
                             LIGGGHTS::ContactModels::NormalModel<LIGGGHTS::ContactModels::LUBRICATED> *normal)
{
  last_pair_model = model;
  last_normal_model = normal;
}

LIGGGHTS::ContactModels::NormalModel<LIGGGHTS::ContactModels::LUBRICATED> *last_pair_normal_model()
{
  return last_normal_model;
}

LIGGGHTS::ContactModels::ContactModelBase *last_pair_contact_model()
{
  return last_pair_model;
}

}    // namespace liggghts
}    // namespace lubricated

namespace {

struct RegisterLubricated {
  RegisterLubricated()
  {
    using namespace LIGGGHTS::ContactModels;
    Factory::instance().addNormalModel("lubricated", LUBRICATED);
    lubricated::liggghts::register_tangential_off();
    lubricated::liggghts::register_tangential_no_history();
    lubricated::liggghts::register_tangential_history();
  }
};

const RegisterLubricated register_lubricated;

}    // namespace

// Lets a test or a launcher check that the library is loaded.
extern "C" __attribute__((visibility("default"))) const char *lubricated_liggghts_version()
{
  return "lubricated 1.0 for LIGGGHTS 3.8.0";
}
