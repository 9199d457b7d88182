#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::CanonicalScene;
using testing::SourcePath;

TEST(SceneLoader, CanonicalSceneHasTheSpecsNumbers) {
  const Scene s = CanonicalScene();
  EXPECT_EQ(s.wall.Position(), vec3(0.0));
  EXPECT_EQ(s.wall.Size(), 1.0);
  EXPECT_EQ(s.wall.GetMaterial(Wall::kLeft).reflectance, Colour(0.75, 0.25, 0.25));
  EXPECT_EQ(s.wall.GetMaterial(Wall::kRight).reflectance, Colour(0.25, 0.75, 0.25));
  for (int side : {Wall::kCeiling, Wall::kFloor, Wall::kBack}) {
    EXPECT_EQ(s.wall.GetMaterial(side).reflectance, Colour(0.75));
  }
  ASSERT_EQ(s.spheres.size(), 2u);
  ASSERT_EQ(s.cubes.size(), 1u);
  EXPECT_EQ(s.spheres[0].Centre(), vec3(0.22, 0.18, 0.40));
  EXPECT_EQ(s.spheres[0].Radius(), 0.18);
  EXPECT_EQ(s.spheres[0].GetMaterial().type, MaterialType::Phong);
  EXPECT_EQ(s.spheres[0].GetMaterial().reflectance, Colour(0.9));
  EXPECT_EQ(s.spheres[0].GetMaterial().exponent, 100.0);
  EXPECT_EQ(s.spheres[1].Centre(), vec3(0.74, 0.16, 0.70));
  EXPECT_EQ(s.spheres[1].Radius(), 0.16);
  EXPECT_EQ(s.spheres[1].GetMaterial().type, MaterialType::Glass);
  EXPECT_EQ(s.spheres[1].GetMaterial().ior, 1.5);
  EXPECT_EQ(s.cubes[0].Position(), vec3(0.42, 0.0, 0.06));
  EXPECT_EQ(s.cubes[0].Size(), 0.28);
  EXPECT_EQ(s.cubes[0].GetMaterial().reflectance, Colour(0.85, 0.75, 0.45));
  // Both spheres rest on the floor.
  EXPECT_EQ(s.spheres[0].Centre().y, s.spheres[0].Radius());
  EXPECT_EQ(s.spheres[1].Centre().y, s.spheres[1].Radius());
  // The light: x and z in [5/12, 7/12] in the plane y = 1, emitting downward.
  ASSERT_TRUE(s.light.has_value());
  const Rectangle& l = s.light->Shape();
  EXPECT_NEAR(l.Corner().x, 5.0 / 12.0, 1e-15);
  EXPECT_NEAR(l.Corner().z, 5.0 / 12.0, 1e-15);
  EXPECT_NEAR(l.PointFromUV(1, 1).x, 7.0 / 12.0, 1e-15);
  EXPECT_NEAR(l.PointFromUV(1, 1).z, 7.0 / 12.0, 1e-15);
  EXPECT_EQ(l.Corner().y, 1.0);
  EXPECT_EQ(s.light->Normal(), vec3(0, -1, 0));
  EXPECT_EQ(s.light->Radiance(), Colour(50.0));
  ASSERT_EQ(s.pointLights.size(), 2u);
  EXPECT_EQ(s.pointLights[0].position, vec3(0.50, 0.98, 0.50));
  EXPECT_EQ(s.pointLights[1].position, vec3(0.02, 0.60, 0.75));
  EXPECT_EQ(s.pointLights[0].intensity, Colour(1.0));
  EXPECT_EQ(s.camera.eye, vec3(0.5, 0.5, 2.5));
  EXPECT_EQ(s.camera.width, 512);
  EXPECT_EQ(s.camera.height, 512);
  EXPECT_EQ(s.whitted.maxDepth, 10);
  EXPECT_EQ(s.ObjectName(0), "W1");
  EXPECT_EQ(s.ObjectName(5), "O1");
}

TEST(SceneLoader, OverridesByJsonPointer) {
  const Scene s = CanonicalScene(
      {"/objects/1/ior=1.3", "/camera/resolution=[64, 32]", "/objects/0/material=mirror"});
  EXPECT_EQ(s.spheres[1].GetMaterial().ior, 1.3);
  EXPECT_EQ(s.camera.width, 64);
  EXPECT_EQ(s.camera.height, 32);
  EXPECT_EQ(s.spheres[0].GetMaterial().type, MaterialType::Mirror);  // a bare word is a string
}

TEST(SceneLoader, LambertianObjectsAreLitAsWalls) {
  const Scene s = LoadScene(testing::SourcePath("scenes/cornell-lambert.json"));
  for (const Material& m : {s.spheres[0].GetMaterial(), s.cubes[0].GetMaterial()}) {
    EXPECT_EQ(m.type, MaterialType::Lambertian);
    EXPECT_EQ(m.whittedDiffuse, 1.0);  // rho / pi * E, as a wall
    EXPECT_EQ(m.whittedSpecular, 0.0);
    EXPECT_EQ(m.WhittedChildWeight(), 0.0);
  }
  EXPECT_EQ(s.spheres[0].GetMaterial().reflectance, Colour(0.9));
  EXPECT_EQ(s.spheres[1].GetMaterial().type, MaterialType::Glass);
}

void ExpectError(const std::vector<std::string>& overrides, const std::string& fragment) {
  try {
    CanonicalScene(overrides);
    ADD_FAILURE() << "accepted: " << overrides.back();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cornell.json"), std::string::npos) << e.what();
  }
}

TEST(SceneLoader, ErrorsNameTheFileTheFieldTheExpectationAndTheValue) {
  ExpectError({"/objects/0/radius=0"},
              "/objects/0/radius: expected a number in (0, 1000000], found the number 0");
  ExpectError({"/objects/2/size=-1"}, "/objects/2/size: expected a number in (0, 1000000]");
  ExpectError({"/objects/1/ior=\"glass\""},
              "/objects/1/ior: expected a number >= 1, found the string \"glass\"");
  ExpectError({"/objects/0/type=cylinder"},
              "/objects/0/type: expected one of \"sphere\" or \"cube\"");
  ExpectError({"/objects/0/reflectance=[0.5, 0.5]"},
              "/objects/0/reflectance: expected an array of 3 numbers");
  ExpectError({"/objects/0/exponent=-3"}, "/objects/0/exponent: expected a number >= 0");
  ExpectError({"/camera/eye=[0.4, 0.5, 2.5]"}, "/camera/eye: expected a point on the axis");
  ExpectError({"/camera/resolution=[0, 10]"}, "/camera/resolution: expected [width, height]");
  ExpectError({"/area_light/center=[0.5, 0.9, 0.5]"},
              "/area_light/center: expected a point in the ceiling plane");
  ExpectError({"/point_lights/0/position=[0.5, 1.5, 0.5]"},
              "/point_lights/0/position: expected a point light inside the room [0, 1]^3, found "
              "one at (0.5, 1.5, 0.5)");
  ExpectError({"/room/walls/1/side=floor"},
              "/room/walls/1/side: expected \"ceiling\" (wall 2; the walls come in the fixed "
              "order left, ceiling, right, floor, back), found the string \"floor\"");
  ExpectError({"/objects/0/whitted_diffuse=0.6", "/objects/0/whitted_specular=0.6"}, "sum to 1");
  ExpectError({"/whitted/spp=0"}, "/whitted/spp: expected a whole number in [1, 1048576]");
  ExpectError({"/objects/0/colour=[1,1,1]"}, "unknown field \"colour\"");
  ExpectError({"/objects/2/position=[0.8, 0.0, 0.06]"},
              "/objects/2/position: expected a cube inside the room [0, 1]^3, found one from "
              "(0.8, 0, 0.06) to (1.08, 0.28, 0.34)");
  ExpectError({"/area_light/side=1.5"},
              "/area_light/side: expected a light inside the ceiling, x in [0, 1] and z in "
              "[0, 1], found one with x from -0.25 to 1.25");
  ExpectError({"/area_light/radiance=[50, -1, 50]"},
              "/area_light/radiance: expected an array of 3 numbers >= 0");
  ExpectError({"/point_lights/1/intensity=[1, 1]"},
              "/point_lights/1/intensity: expected an array of 3 numbers");
  ExpectError({"/room/size=0"}, "/room/size: expected a number in (0, 1000000]");
  ExpectError({"/mc/max_depth=0"}, "/mc/max_depth: expected a whole number in [1, 64]");
  ExpectError({"/whitted/exposure=-1"}, "/whitted/exposure: expected a number > 0");
  ExpectError({"/objects/0/center=[1e300, 0, 0]"},
              "/objects/0/center: expected an array of 3 numbers in [-1000000, 1000000]");
  ExpectError({"/camera/resolution=[64, 64, 64]"}, "/camera/resolution: expected [width, height]");
  ExpectError({"/objects/1/material=wood"},
              "/objects/1/material: expected one of \"phong\", \"mirror\", \"glass\" or "
              "\"lambertian\"");
  // One rule for every material: a field it does not use is refused, with the reason.
  ExpectError({"/objects/0/material=lambertian"},
              "/objects/0/exponent: material \"lambertian\" has no field \"exponent\" (it "
              "reflects rho/pi, as a wall, and has no highlight): delete it");
  ExpectError({"/objects/1/material=lambertian", "/objects/1/reflectance=[0.5, 0.5, 0.5]"},
              "/objects/1/ior: material \"lambertian\" has no field \"ior\"");
  ExpectError({"/objects/1/reflectance=[0.5, 0.5, 0.5]"},
              "/objects/1/reflectance: material \"glass\" has no field \"reflectance\" (glass "
              "is clear");
  ExpectError({"/objects/1/reflectance=[0.5, 0.5, 0.5]"},
              "): delete it (with --set: /objects/1/reflectance=null)");
  ExpectError({"/objects/0/ior=1.5"},
              "/objects/0/ior: material \"phong\" has no field \"ior\" (only glass refracts)");
  ExpectError({"/objects/0/material=mirror", "/objects/0/ior=1.5"},
              "/objects/0/ior: material \"mirror\" has no field \"ior\"");
  // Numbers as people write them, computed ones rounded: 0.6 + 0.5, not 1.100000.
  ExpectError({"/objects/0/whitted_diffuse=0.6", "/objects/0/whitted_specular=0.5"},
              "found 0.6 + 0.5");
  ExpectError({"/camera/eye=[0.5, 0.6, 2.5]"},
              "/camera/eye: expected a point on the axis of the back wall in front of the room, "
              "(0.5, 0.5, z > 1), found (0.5, 0.6, 2.5)");
  ExpectError({"/objects/0/center=[0.1, 0.18, 0.4]"},
              "found one from (-0.08, 0, 0.22) to (0.28, 0.36, 0.58)");
  // Two parts with one name would make messages and glint tree ambiguous.
  ExpectError({"/objects/2/id=\"O1\""},
              "/objects/2/id: expected an id that no other part of the scene has, found \"O1\", "
              "already the id of /objects/0");
  ExpectError({"/point_lights/1/id=\"W3\""}, "already the id of /room/walls/2");
  ExpectError({"/description=7"}, "/description: expected a non-empty string, found the number 7");
}

TEST(SceneLoader, SyntaxErrorsGiveLineAndColumn) {
  try {
    LoadScene(SourcePath("tests/scene/bad-scenes/bad-syntax.json"));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad-syntax.json:5:"), std::string::npos) << e.what();
  }
}

std::string ParseError(const std::string& text) {
  try {
    ParseJsonText(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SceneLoader, CommentsAndTrailingCommasGetWhereAndAPlainSentence) {
  EXPECT_EQ(ParseError("{\n  // the room\n  \"room\": 1\n}"),
            "s.json:2:3: a comment, and JSON has none: delete it (the \"description\" field "
            "holds free text)");
  EXPECT_EQ(ParseError("{\"a\": 1 /* why */}"),
            "s.json:1:9: a comment, and JSON has none: delete it (the \"description\" field "
            "holds free text)");
  EXPECT_EQ(ParseError("{\"a\": [1, 2,\n ],\n \"b\": 3}"),
            "s.json:1:12: a comma after the last element of a list or object, which JSON does "
            "not allow: delete it");
  EXPECT_EQ(ParseError("{\"a\": 1,}"),
            "s.json:1:8: a comma after the last element of a list or object, which JSON does "
            "not allow: delete it");
  // Slashes and commas inside strings are text: the real mistake is reported.
  EXPECT_EQ(ParseError("{\"description\": \"see http://x, ]\", \"a\": 1,}"),
            "s.json:1:42: a comma after the last element of a list or object, which JSON does "
            "not allow: delete it");
  // Any other syntax error keeps the parser's words, with line and column.
  EXPECT_NE(ParseError("{\"a\": tru}").find("s.json:1:10: invalid JSON: "), std::string::npos);
  EXPECT_EQ(ParseError("{\"a\": \"//\"}"), "accepted");
}

TEST(SceneLoader, ADefaultIdTakenByAnotherPartIsRefused) {
  nlohmann::json document = LoadSceneDocument(SourcePath("scenes/cornell.json"), {});
  document["objects"][1].erase("id");
  document["objects"][0]["id"] = "O2";
  try {
    SceneFromJson(document, "cornell.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "cornell.json: /objects/1/id: expected an id that no other part of the scene "
                 "has, found nothing, and the default \"O2\", already the id of /objects/0");
  }
}

TEST(SceneLoader, NullRemovesAField) {
  // A phong cube made glass: its reflectance must go, and --set can take it away.
  const Scene s = CanonicalScene(
      {"/objects/2/material=glass", "/objects/2/ior=1.5", "/objects/2/reflectance=null"});
  EXPECT_EQ(s.cubes[0].GetMaterial().type, MaterialType::Glass);
}

TEST(SceneLoader, PointLightsAreNamedP1P2ByDefault) {
  nlohmann::json document = LoadSceneDocument(SourcePath("scenes/cornell.json"), {});
  for (nlohmann::json& p : document["point_lights"]) p.erase("id");
  const Scene s = SceneFromJson(document, "cornell.json");
  ASSERT_EQ(s.pointLights.size(), 2u);
  EXPECT_EQ(s.ObjectName(s.pointLights[0].object), "P1");
  EXPECT_EQ(s.ObjectName(s.pointLights[1].object), "P2");
}

TEST(SceneLoader, BadOverridesAreRejected) {
  ExpectError({"objects/1/ior=1.3"}, "expected POINTER=VALUE");
  ExpectError({"/nothing/here=1"}, "the scene has no field /nothing");
  ExpectError({"/objects/7/ior=1.3"}, "no element 7");
}

TEST(SceneLoader, DidYouMean) {
  EXPECT_EQ(EditDistance("radious", "radius"), 1u);
  EXPECT_EQ(EditDistance("", "abc"), 3u);
  ExpectError({"/objects/0/exponant=3"}, "did you mean \"exponent\"?");
}

TEST(SceneLoader, FuzzCorpusAndRegressionsLoadOrFailCleanly) {
  // Every seed and every input the fuzzer once crashed on: a scene or an InputError.
  int files = 0;
  for (const char* dir :
       {"tests/scene/fuzz/corpus", "tests/scene/fuzz/regressions", "tests/scene/bad-scenes"}) {
    for (const auto& entry : std::filesystem::directory_iterator(SourcePath(dir))) {
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      ++files;
      try {
        SceneFromJson(ParseJsonText(text.str(), entry.path().string()), entry.path().string());
      } catch (const InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << ": " << e.what();
      }
    }
  }
  EXPECT_GT(files, 10);
}

TEST(SceneLoader, OverlapsAreWarnedAbout) {
  EXPECT_TRUE(CanonicalScene().warnings.empty());  // touching the floor is no overlap
  const Scene s = CanonicalScene({"/objects/1/center=[0.6, 0.16, 0.3]"});
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("objects O2 and O3 overlap"), std::string::npos) << s.warnings[0];
  const Scene t = CanonicalScene({"/objects/0/center=[0.6, 0.18, 0.6]"});
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_NE(t.warnings[0].find("O1 and O2"), std::string::npos) << t.warnings[0];
}

}  // namespace
}  // namespace glint
