// test_parameters.cpp - scene parameters and "= expression" values (scene/parameters.h): arithmetic with
// precedence and associativity, functions, parameters defined from other parameters in any order, --set of a
// parameter, and clear errors for unknown names and circular definitions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/parameters.h"
#include "scene/scene_loader.h"

namespace cdmpm {
namespace {

double eval(const std::string& expr, nlohmann::json params = nlohmann::json::object()) {
  nlohmann::json j = {{"parameters", params}, {"v", "=" + expr}};
  substitute_parameters(j, "t.json");
  EXPECT_FALSE(j.contains("parameters"));
  return j["v"].get<double>();
}

TEST(SceneParameters, ArithmeticFollowsUsualPrecedence) {
  EXPECT_EQ(eval("1 + 2 * 3"), 7);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9);
  EXPECT_EQ(eval("8 / 4 / 2"), 1);        // left associative
  EXPECT_EQ(eval("2 ^ 3 ^ 2"), 512);      // right associative
  EXPECT_EQ(eval("-2 ^ 2"), 4);           // unary minus binds tighter than ^ here: (-2)^2
  EXPECT_EQ(eval("1.5e2 - .5"), 149.5);
  EXPECT_DOUBLE_EQ(eval("sqrt(2) * sqrt(2)"), 2);
  EXPECT_DOUBLE_EQ(eval("tan(45 * pi / 180)"), 1);
  EXPECT_EQ(eval("max(3, min(1, 2))"), 3);
}

TEST(SceneParameters, ParametersMayUseEachOtherInAnyOrder) {
  EXPECT_EQ(eval("x_edge + H", {{"x_edge", "= 9 * H"}, {"H", 100}}), 1000);
}

TEST(SceneParameters, SetOverridesAParameterBeforeEvaluation) {
  nlohmann::json j = {{"parameters", {{"D", 0.4}}},
                      {"dim", 2},
                      {"domain", {{"size", {1.0, 1.0}}, {"dx", "= 0.1 * D"}}},
                      {"time", {{"end", 1.0}, {"frame_interval", 0.5}}},
                      {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e5}}}}},
                      {"bodies", {{{"material", "water"}, {"particles_per_cell", 4},
                                   {"shape", {{"type", "box"}, {"min", {0, 0}}, {"max", {0.5, 0.5}}}}}}}};
  EXPECT_DOUBLE_EQ(scene_from_json(j, "t.json").domain.dx, 0.04);
  EXPECT_DOUBLE_EQ(scene_from_json(j, "t.json", {"parameters.D=0.5"}).domain.dx, 0.05);
}

// An expression with an integral value is an integer, so integer keys accept it; other values stay numbers,
// and a literal 4.0 is still not an integer.
TEST(SceneParameters, IntegralExpressionsFillIntegerKeys) {
  auto scene = [](nlohmann::json ppc) {
    return nlohmann::json{{"parameters", {{"n", 2}}},
                          {"dim", 2},
                          {"domain", {{"size", {1.0, 1.0}}, {"dx", 0.1}}},
                          {"time", {{"end", 1.0}, {"frame_interval", 0.5}}},
                          {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e5}}}}},
                          {"bodies", {{{"material", "water"}, {"particles_per_cell", ppc},
                                       {"shape", {{"type", "box"}, {"min", {0, 0}}, {"max", {0.5, 0.5}}}}}}}};
  };
  EXPECT_EQ(scene_from_json(scene("= n^2"), "t.json").bodies[0].particles_per_cell, 4);
  for (const nlohmann::json& bad : {nlohmann::json("= n^2 + 0.5"), nlohmann::json(4.0)}) {
    try {
      scene_from_json(scene(bad), "t.json");
      ADD_FAILURE() << bad << " accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("particles_per_cell: expected an integer"), std::string::npos) << e.what();
    }
  }
}

TEST(SceneParameters, ErrorsNameThePathAndTheProblem) {
  auto message = [](nlohmann::json j) {
    try {
      substitute_parameters(j, "t.json");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{"a", {1, "= 2 * nope"}}}).find("t.json: a[1]: expected a number or an expression"), std::string::npos);
  EXPECT_NE(message({{"a", {1, "= 2 * nope"}}}).find("unknown parameter 'nope'"), std::string::npos);
  EXPECT_NE(message({{"a", "= (1 + 2"}}).find("expected ')'"), std::string::npos);
  EXPECT_NE(message({{"parameters", {{"p", "= q"}, {"q", "= p"}}}}).find("parameters.p"), std::string::npos);
  EXPECT_NE(message({{"a", "= 1 / 0"}}).find("not finite"), std::string::npos);
}

}  // namespace
}  // namespace cdmpm
