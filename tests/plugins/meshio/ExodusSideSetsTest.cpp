// SPDX-License-Identifier: MIT
// Exodus side sets: a small file written here with the netCDF library (a hexahedron and a
// wedge, a side set naming sides of each) reads as the node sets of those sides' nodes,
// by the Exodus manual's side numbering; a side number past the element's is an error.
#include "support/ReaderSupport.hpp"
#include "support/TestSupport.hpp"

#include <volpost/core/EntitySet.hpp>

#include <netcdf.h>

#include <set>
#include <string>
#include <vector>

using namespace volpost;
using volpost::test::meshioReaders;

namespace {

void check(int status) { ASSERT_EQ(status, NC_NOERR) << nc_strerror(status); }

// Nodes 1..8: the unit cube; 9..14: a wedge beside it (x from 2 to 3).
void writeExodus(const std::string& path, const std::vector<int>& elements, const std::vector<int>& sides) {
  int nc = 0;
  check(nc_create(path.c_str(), NC_CLOBBER, &nc));
  int dNodes, dDim, dElem, dBlk, dIn1, dPer1, dIn2, dPer2, dSets, dSide1;
  check(nc_def_dim(nc, "num_nodes", 14, &dNodes));
  check(nc_def_dim(nc, "num_dim", 3, &dDim));
  check(nc_def_dim(nc, "num_elem", 2, &dElem));
  check(nc_def_dim(nc, "num_el_blk", 2, &dBlk));
  check(nc_def_dim(nc, "num_el_in_blk1", 1, &dIn1));
  check(nc_def_dim(nc, "num_nod_per_el1", 8, &dPer1));
  check(nc_def_dim(nc, "num_el_in_blk2", 1, &dIn2));
  check(nc_def_dim(nc, "num_nod_per_el2", 6, &dPer2));
  check(nc_def_dim(nc, "num_side_sets", 1, &dSets));
  check(nc_def_dim(nc, "num_side_ss1", elements.size(), &dSide1));
  int vx, vy, vz, c1, c2, es, ss, sp;
  check(nc_def_var(nc, "coordx", NC_DOUBLE, 1, &dNodes, &vx));
  check(nc_def_var(nc, "coordy", NC_DOUBLE, 1, &dNodes, &vy));
  check(nc_def_var(nc, "coordz", NC_DOUBLE, 1, &dNodes, &vz));
  const int shape1[2] = {dIn1, dPer1}, shape2[2] = {dIn2, dPer2};
  check(nc_def_var(nc, "connect1", NC_INT, 2, shape1, &c1));
  check(nc_put_att_text(nc, c1, "elem_type", 4, "HEX8"));
  check(nc_def_var(nc, "connect2", NC_INT, 2, shape2, &c2));
  check(nc_put_att_text(nc, c2, "elem_type", 5, "WEDGE"));
  check(nc_def_var(nc, "elem_ss1", NC_INT, 1, &dSide1, &es));
  check(nc_def_var(nc, "side_ss1", NC_INT, 1, &dSide1, &ss));
  check(nc_def_var(nc, "ss_prop1", NC_INT, 1, &dSets, &sp));
  check(nc_enddef(nc));
  const double x[14] = {0, 1, 1, 0, 0, 1, 1, 0, 2, 3, 2, 2, 3, 2};
  const double y[14] = {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 1};
  const double z[14] = {0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 1, 1, 1};
  check(nc_put_var_double(nc, vx, x));
  check(nc_put_var_double(nc, vy, y));
  check(nc_put_var_double(nc, vz, z));
  const int hex[8] = {1, 2, 3, 4, 5, 6, 7, 8}, wedge[6] = {9, 10, 11, 12, 13, 14};
  check(nc_put_var_int(nc, c1, hex));
  check(nc_put_var_int(nc, c2, wedge));
  check(nc_put_var_int(nc, es, elements.data()));
  check(nc_put_var_int(nc, ss, sides.data()));
  const int id = 7;
  check(nc_put_var_int(nc, sp, &id));
  check(nc_close(nc));
}

std::set<std::int64_t> nodesOf(const Model& m, const std::string& name) {
  const EntitySet* s = findSet(m.sets, name);
  EXPECT_NE(s, nullptr) << name;
  std::set<std::int64_t> ids;
  if (s)
    for (const std::uint32_t n : s->members) ids.insert(m.mesh().nodeId(n));
  return ids;
}

}  // namespace

TEST(ExodusSideSets, SidesBecomeTheNodeSetsOfTheirNodes) {
  const auto side = [](int element, int number) {
    const std::string path = ::testing::TempDir() + "/sides.exo";
    writeExodus(path, {element}, {number});
    return nodesOf(*meshioReaders().load(path), "side set 7");
  };
  EXPECT_EQ(side(1, 1), (std::set<std::int64_t>{1, 2, 6, 5}));
  EXPECT_EQ(side(1, 4), (std::set<std::int64_t>{1, 5, 8, 4}));
  EXPECT_EQ(side(1, 5), (std::set<std::int64_t>{1, 4, 3, 2}));
  EXPECT_EQ(side(1, 6), (std::set<std::int64_t>{5, 6, 7, 8}));
  EXPECT_EQ(side(2, 1), (std::set<std::int64_t>{9, 10, 13, 12}));
  EXPECT_EQ(side(2, 3), (std::set<std::int64_t>{9, 12, 14, 11}));
  EXPECT_EQ(side(2, 4), (std::set<std::int64_t>{9, 11, 10}));
  EXPECT_EQ(side(2, 5), (std::set<std::int64_t>{12, 13, 14}));
  const std::string path = ::testing::TempDir() + "/both.exo";
  writeExodus(path, {1, 2}, {6, 5});
  EXPECT_EQ(nodesOf(*meshioReaders().load(path), "side set 7"), (std::set<std::int64_t>{5, 6, 7, 8, 12, 13, 14}));
}

TEST(ExodusSideSets, ASidePastTheElementsOrAnUnknownElementIsAnError) {
  const auto error = [](int element, int number) {
    const std::string path = ::testing::TempDir() + "/bad_sides.exo";
    writeExodus(path, {element}, {number});
    try {
      meshioReaders().load(path);
    } catch (const ReadError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  EXPECT_NE(error(2, 6).find("side_ss1 (side set 7) names side 6 of a wedge6"), std::string::npos) << error(2, 6);
  EXPECT_NE(error(3, 1).find("elem_ss1 (side set 7) names element 3 of 2"), std::string::npos) << error(3, 1);
}
