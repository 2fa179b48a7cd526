/* -*- c++ -*- ----------------------------------------------------------
   A fix whose sustained contacts join the contact-network check of pair_style
   lubricated/springdashpot (contact_network_check.h): the plugin's wall fixes. The check
   finds every fix that is one at each set-up.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_CONTACT_NETWORK_PARTICIPANT_H
#define LMP_LUBRICATED_CONTACT_NETWORK_PARTICIPANT_H

#include "lmptype.h"

#include "lubricated/contact.h"

#include <vector>

namespace LAMMPS_NS {

class ContactNetworkParticipant {
 public:
  // A contact of the last evaluation in overlap then and a step before (sustained): the atom's
  // ID and the normal from the wall to the atom. By ID: a dry wall's are the last step's, whose
  // atoms a rebuild may have reordered since.
  struct SustainedContact {
    tagint tag;
    double n[3];
  };
  virtual const std::vector<SustainedContact> &sustained_contacts() const = 0;
  virtual const lubricated::ContactModel &contact_model() const = 0;
  virtual const lubricated::Coefficients &coefficients() const = 0;

 protected:
  ~ContactNetworkParticipant() = default;
};

}    // namespace LAMMPS_NS

#endif
