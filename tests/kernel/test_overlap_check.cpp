// The overlap check's levels, bound and message (src/lubricated/overlap_check.h).
#include "lubricated/overlap_check.h"

#include <gtest/gtest.h>

#include <string>

using namespace lubricated;

TEST(OverlapCheck, LevelsAndTheContactTimeThatKeepsItBelow)
{
  EXPECT_EQ(overlap_level(overlap_fraction(-0.05e-3, 1e-3)), OverlapLevel::none);
  EXPECT_EQ(overlap_level(overlap_fraction(-0.2e-3, 1e-3)), OverlapLevel::warning);
  EXPECT_EQ(overlap_level(overlap_fraction(-0.6e-3, 1e-3)), OverlapLevel::error);
  EXPECT_DOUBLE_EQ(overlap_distance(1e-3, 1e-4, 0.5), 1.1e-3 - 0.5e-4);
  EXPECT_DOUBLE_EQ(contact_time_below(8e-4, 0.8, 0.5), 5e-4);
  Coefficients c;
  c.e_dry = 0.5, c.n_contact = 8, c.settled_contact_time = 8e-4;
  const std::string text = overlap_message("atoms 1 and 2 (types 1 2)", -0.8e-4, 1e-4, 0.8, c, 1e-4, false);
  EXPECT_NE(text.find("overlap by 0.8 of the smaller radius"), std::string::npos) << text;
  EXPECT_NE(text.find("t_c = 0.0008 (N_c = 8 steps of 0.0001)"), std::string::npos) << text;
  EXPECT_NE(text.find("t_c <= 0.0005 brings this overlap to 0.5 of the radius"), std::string::npos) << text;
  EXPECT_NE(text.find("tcontact 0.0005"), std::string::npos) << text;
  const std::string wall =
      overlap_message("atom 1 (type 1) and the wall of fix floor", -0.2e-3, 1e-3, 0.2, c, 1e-4, false, true);
  EXPECT_NE(wall.find("overlap by 0.2 of the sphere's radius"), std::string::npos) << wall;
  EXPECT_NE(wall.find("reported once per run"), std::string::npos) << wall;
  EXPECT_NE(text.find("ncontact 8 from a first run at a time step of 6.25e-05"), std::string::npos) << text;
}

TEST(OverlapCheck, LiggghtsNamesItsProperties)
{
  // LIGGGHTS: t_c = N_c dt at every time step, one value for all type pairs.
  Coefficients c;
  c.e_dry = 0.5, c.n_contact = 8;
  const ContactTimeNames names{"lubricatedContactTime", "lubricatedContactSteps", true, false};
  const std::string text =
      overlap_message("atoms 1 and 2 (types 1 2)", -0.8e-4, 1e-4, 0.8, c, 1e-4, false, false, names);
  EXPECT_NE(text.find("t_c = 0.0008 (N_c = 8 steps of 0.0001)"), std::string::npos) << text;
  EXPECT_NE(text.find("lubricatedContactTime 0.0005, or a time step of 6.25e-05 or less with lubricatedContactSteps 8"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("ncontact"), std::string::npos) << text;
  EXPECT_EQ(text.find("per-type-pair"), std::string::npos) << text;
  c.t_contact = 8e-4;
  const std::string timed =
      overlap_message("atoms 1 and 2 (types 1 2)", -0.8e-4, 1e-4, 0.8, c, 1e-4, false, false, names);
  EXPECT_NE(timed.find("lubricatedContactTime 0.0005 (doc/model.rst"), std::string::npos) << timed;
}
