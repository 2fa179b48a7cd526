// The text of the properties model lubricated reads, checked as LAMMPS's utils::numeric checks a
// number (issue 18: LIGGGHTS's fix property/global converts "1e" to 1 without a word).
//
// LIGGGHTS keeps no text of a property, so the check runs when the property is defined: this
// library interposes fix property/global's constructor (libliggghts calls it through its PLT,
// and this library precedes libliggghts in the lookup order both with LD_PRELOAD and in the
// liggghts-lubricated launcher, which links it first), checks the values of the properties
// the model reads and that its global ones are given as scalars, then calls LIGGGHTS's own
// constructor. Other properties are left to LIGGGHTS.
#include "error.h"
#include "lammps.h"

#include "liggghts/lubricated_properties.h"

#include <dlfcn.h>

#include <cctype>
#include <cstring>
#include <string>

// The complete-object constructor FixPropertyGlobal::FixPropertyGlobal(LAMMPS *, int, char **).
#define LUBRICATED_PROPERTY_CONSTRUCTOR "_ZN9LAMMPS_NS17FixPropertyGlobalC1EPNS_6LAMMPSEiPPc"

namespace {

using Constructor = void (*)(void *, LAMMPS_NS::LAMMPS *, int, char **);

bool read_by_model(const char *name)
{
  return std::strncmp(name, "lubricated", 10) == 0 || std::strcmp(name, "coefficientRestitution") == 0;
}

// A decimal floating-point number as LAMMPS accepts one: [+-] digits [. digits] [(e|E) [+-] digits],
// at least one digit before the exponent; no hex, inf or nan.
bool is_number(const char *text)
{
  const char *c = text;
  if (*c == '+' || *c == '-') ++c;
  int digits = 0;
  while (std::isdigit(static_cast<unsigned char>(*c)))
    ++c, ++digits;
  if (*c == '.') {
    ++c;
    while (std::isdigit(static_cast<unsigned char>(*c)))
      ++c, ++digits;
  }
  if (digits == 0) return false;
  if (*c == 'e' || *c == 'E') {
    ++c;
    if (*c == '+' || *c == '-') ++c;
    if (!std::isdigit(static_cast<unsigned char>(*c))) return false;
    while (std::isdigit(static_cast<unsigned char>(*c)))
      ++c;
  }
  return *c == '\0';
}

// The first value of fix ID group property/global name kind [ncols] values...
int first_value(const char *kind)
{
  const bool matrix = std::strcmp(kind, "matrix") == 0 || std::strcmp(kind, "peratomtypepair") == 0 ||
                      std::strcmp(kind, "atomtypepair") == 0;
  return matrix ? 6 : 5;
}

}    // namespace

extern "C" __attribute__((visibility("default"))) void
lubricated_checked_property_global(void *self, LAMMPS_NS::LAMMPS *lmp, int narg,
                                   char **arg) __asm__(LUBRICATED_PROPERTY_CONSTRUCTOR);

extern "C" void lubricated_checked_property_global(void *self, LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  // LIGGGHTS's lookup by style skips a scalar property given in another style without a word.
  if (narg > 4 && lubricated::liggghts::is_scalar_property(arg[3]) && std::strcmp(arg[4], "scalar") != 0) {
    static std::string message;    // LIGGGHTS's Error keeps a pointer to the text
    message = lubricated::liggghts::scalar_style_error(arg[0], arg[3], arg[4]);
    lmp->error->all(FLERR, message.c_str());
  }
  if (narg > 5 && read_by_model(arg[3]))
    for (int k = first_value(arg[4]); k < narg; k++)
      if (!is_number(arg[k]))
        lmp->error->all(FLERR, ("model lubricated: fix " + std::string(arg[0]) + " property/global " + arg[3] + ": '" +
                                arg[k] + "' is not a number (expected a value such as 0.9 or 1e-3)")
                                   .c_str());
  static const Constructor liggghts_constructor =
      reinterpret_cast<Constructor>(dlsym(RTLD_NEXT, LUBRICATED_PROPERTY_CONSTRUCTOR));
  if (!liggghts_constructor)
    lmp->error->all(FLERR, "model lubricated: LIGGGHTS's fix property/global constructor not found");
  liggghts_constructor(self, lmp, narg, arg);
}
