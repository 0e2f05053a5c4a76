// test_section_probe_input.cpp - the "section" probe (probe/section.cpp): bad keys and sections outside the domain
// are refused naming the key.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "probe/probes.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm::testing {
namespace {

// Input errors: the loader names the key and what it expected.
TEST(SectionProbe, InputErrorsNameTheKey) {
  auto refused = [](const nlohmann::json& j) -> std::string {
    try {
      scene_from_json(j, "section.json");
    } catch (const SceneError& e) {
      return e.what();
    }
    return "accepted";
  };
  auto has = [](const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; };
  std::string m = refused(section_tank(2, 1, 0.1, 1, 4, 0, 0.1, {{"position", {5.0}}}));
  EXPECT_TRUE(has(m, "section.json") && has(m, "probes.list[0].position") && has(m, "inside the domain")) << m;
  m = refused(section_tank(2, 1, 0.1, 1, 4, 0, 0.1, {{"position", {2.0}}, {"points", 3}}));
  EXPECT_TRUE(has(m, "probes.list[0].points") && has(m, "unknown key")) << m;
  m = refused(section_tank(2, 1, 0.1, 1, 4, 0, 0.1, {{"position", {2.0, 1.0}}}));
  EXPECT_TRUE(has(m, "probes.list[0].position")) << m;
  m = refused(section_tank(3, 1, 0.1, 1, 4, 1, 0.2, {{"start", {1.0, 0.0}}, {"end", {1.0, 2.0}}, {"points", 3}}));
  EXPECT_TRUE(has(m, "probes.list[0].end") && has(m, "inside the domain")) << m;
  m = refused(section_tank(3, 1, 0.1, 1, 4, 1, 0.2, {{"start", {1.0, 0.5}}, {"end", {1.0, 0.5}}, {"points", 3}}));
  EXPECT_TRUE(has(m, "probes.list[0].end") && has(m, "different from start")) << m;
  m = refused(section_tank(3, 1, 0.1, 1, 4, 1, 0.2, {{"start", {1.0, 0.0}}, {"end", {1.0, 1.0}}, {"points", 1}}));
  EXPECT_TRUE(has(m, "probes.list[0].points") && has(m, "integer")) << m;
  m = refused(section_tank(3, 1, 0.1, 1, 4, 1, 0.2, {{"start", {1.0, 0.0}}, {"end", {1.0, 1.0}}}));
  EXPECT_TRUE(has(m, "probes.list[0].points") && has(m, "required")) << m;
  m = refused(section_tank(3, 1, 0.1, 1, 4, 1, 0.2, {{"position", {1.0, 0.0}}}));
  EXPECT_TRUE(has(m, "probes.list[0].position") && has(m, "unknown key")) << m;
  m = refused(section_tank(2, 1, 0.1, 1, 4, 0, 0.1, {{"position", {2.0}}, {"still_level", "high"}}));
  EXPECT_TRUE(has(m, "probes.list[0].still_level") && has(m, "a number")) << m;
}

}  // namespace
}  // namespace cdmpm::testing
