#include <gtest/gtest.h>

#include "glint/camera/Camera.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

// The eye, a view-plane corner and the matching front corner of the room are collinear.
void ExpectCollinear(vec3 eye, vec3 planeCorner, vec3 roomCorner) {
  const vec3 a = glm::normalize(planeCorner - eye);
  const vec3 b = glm::normalize(roomCorner - eye);
  EXPECT_NEAR(glm::length(glm::cross(a, b)), 0.0, 1e-14);
}

void CheckSetUpRule(const Wall& room, vec3 eye, double expectedDistance) {
  const Camera camera(room, eye, 64, 64);
  EXPECT_NEAR(camera.ViewPlaneDistance(), expectedDistance, 1e-14);
  EXPECT_EQ(camera.ViewDirection(), vec3(0, 0, -1));
  const vec3 p = room.Position();
  const double s = room.Size();
  const double front = p.z + s;
  ExpectCollinear(eye, camera.ViewPlanePoint(0, 0), vec3(p.x, p.y + s, front));       // top left
  ExpectCollinear(eye, camera.ViewPlanePoint(64, 0), vec3(p.x + s, p.y + s, front));  // top right
  ExpectCollinear(eye, camera.ViewPlanePoint(0, 64), vec3(p.x, p.y, front));          // bottom left
  ExpectCollinear(eye, camera.ViewPlanePoint(64, 64), vec3(p.x + s, p.y, front));
  // The view plane is [-s/2, s/2]^2 around the axis.
  EXPECT_NEAR(camera.HalfWidth(), 0.5 * s, 1e-15);
  EXPECT_NEAR(camera.HalfHeight(), 0.5 * s, 1e-15);
}

TEST(Camera, SetUpRuleForTheCanonicalEye) {
  CheckSetUpRule(Wall(), vec3(0.5, 0.5, 2.5), 1.5);
  // Vertical field of view 2 atan(1/3) = 36.87 degrees (the spec).
  const Camera camera(Wall(), vec3(0.5, 0.5, 2.5), 512, 512);
  const double fov = 2.0 * std::atan(camera.HalfHeight() / camera.ViewPlaneDistance());
  EXPECT_NEAR(fov * 180.0 / kPi, 36.8699, 1e-4);
}

TEST(Camera, SetUpRuleForOtherEyesAndRooms) {
  CheckSetUpRule(Wall(), vec3(0.5, 0.5, 4.0), 3.0);
  CheckSetUpRule(Wall(vec3(1, 2, 3), 2.0, {}), vec3(2, 3, 5.5), 0.5);
}

// The design: "change the distance from the eye to the view plane while you keep the
// view plane size unchanged". The plane keeps its size; the field of view follows.
TEST(Camera, ViewPlaneDistanceKeepsThePlaneSize) {
  for (const double d : {0.75, 1.5, 3.0}) {
    const Camera camera(Wall(), vec3(0.5, 0.5, 2.5), 64, 32, d);
    EXPECT_EQ(camera.ViewPlaneDistance(), d);
    EXPECT_EQ(camera.HalfHeight(), 0.5);
    EXPECT_EQ(camera.HalfWidth(), 1.0);
    // The top-left corner of the plane is (-1, 0.5) around the axis, at distance d.
    const vec3 corner = camera.ViewPlanePoint(0, 0);
    EXPECT_NEAR(corner.x, -0.5, 1e-15);
    EXPECT_NEAR(corner.y, 1.0, 1e-15);
    EXPECT_NEAR(corner.z, 2.5 - d, 1e-15);
  }
  // Twice the distance, half the tangent of the half-angle: 2 atan(1/6) vertically.
  const Camera narrow(Wall(), vec3(0.5, 0.5, 2.5), 64, 64, 3.0);
  const vec3 top = narrow.DirectionThrough(32, 0);
  EXPECT_NEAR(top.y / -top.z, 1.0 / 6.0, 1e-14);
  // 0 is the set-up rule's, and a scene's settings carry the distance.
  EXPECT_EQ(Camera(Wall(), vec3(0.5, 0.5, 2.5), 8, 8, 0.0).ViewPlaneDistance(), 1.5);
  const Scene scene = testing::CanonicalScene({"/camera/view_plane_distance=2.25"});
  EXPECT_EQ(Camera(scene.wall, scene.camera, 8, 8).ViewPlaneDistance(), 2.25);
  EXPECT_THROW(Camera(Wall(), vec3(0.5, 0.5, 2.5), 8, 8, -1.0), std::invalid_argument);
}

TEST(Camera, EyeOffTheAxisIsRejected) {
  EXPECT_THROW(Camera(Wall(), vec3(0.4, 0.5, 2.5), 8, 8), std::invalid_argument);
  EXPECT_THROW(Camera(Wall(), vec3(0.5, 0.5, 0.9), 8, 8), std::invalid_argument);
  EXPECT_THROW(Camera(Wall(), vec3(0.5, 0.5, 2.5), 0, 8), std::invalid_argument);
}

TEST(Camera, PixelZeroIsTopLeft) {
  const Camera camera(Wall(), vec3(0.5, 0.5, 2.5), 4, 4);
  const vec3 d = camera.DirectionThrough(0.5, 0.5);
  EXPECT_LT(d.x, 0.0);  // left
  EXPECT_GT(d.y, 0.0);  // up
}

// Renders with 1 and with 2 threads; the images must be bit-identical. Returns the image.
Image ExpectSameForOneAndTwoThreads(const Scene& scene, const Integrator& integrator, int width,
                                    int height, int spp, std::uint64_t seed) {
  RenderOptions options;
  options.raysPerPixel = spp;
  options.seed = seed;
  Camera one(scene.wall, scene.camera, width, height);
  Camera two(scene.wall, scene.camera, width, height);
  options.threads = 1;
  const RenderStats s1 = one.Render(integrator, options);
  options.threads = 2;
  const RenderStats s2 = two.Render(integrator, options);
  const Image a = one.ToImage();
  const Image b = two.ToImage();
  for (std::size_t i = 0; i < a.Pixels().size(); ++i) {
    EXPECT_EQ(a.Pixels()[i], b.Pixels()[i]) << "pixel " << i;
  }
  EXPECT_EQ(s1.TracedRays(), s2.TracedRays());
  EXPECT_EQ(s1.shadowRays, s2.shadowRays);
  EXPECT_EQ(s1.cameraRays, static_cast<std::uint64_t>(width) * height * spp);
  return a;
}

TEST(Camera, SameSeedSameImageForAnyThreadCount) {
  const Scene scene = testing::CanonicalScene();
  const WhittedIntegrator integrator(scene, 10);
  const Image a = ExpectSameForOneAndTwoThreads(scene, integrator, 40, 30, 3, 42);
  // A different seed moves the sample points, so the image changes.
  const Image c = ExpectSameForOneAndTwoThreads(scene, integrator, 40, 30, 3, 43);
  int differing = 0;
  for (std::size_t i = 0; i < a.Pixels().size(); ++i) differing += a.Pixels()[i] != c.Pixels()[i];
  EXPECT_GT(differing, 100);
}

TEST(Camera, MonteCarloImageDoesNotDependOnTheThreadCount) {
  const Scene scene = testing::CanonicalScene();
  MonteCarloOptions o;
  o.walls = MonteCarloOptions::Walls::Diffuse;
  o.branches = 2;
  ExpectSameForOneAndTwoThreads(scene, MonteCarloIntegrator(scene, o), 33, 17, 8, 7);
}

TEST(Camera, LightTracingsSplatsDoNotDependOnTheThreadCount) {
  // Light paths land in any pixel, from any thread: their sums are integers (Pixel::AddSplat).
  const Scene scene = testing::CanonicalScene();
  MonteCarloOptions o;
  o.walls = MonteCarloOptions::Walls::Diffuse;
  o.caustics = MonteCarloOptions::Caustics::Light;
  const MonteCarloIntegrator integrator(scene, o,
                                        Camera::GeometryFor(scene.wall, scene.camera, 33, 17));
  ExpectSameForOneAndTwoThreads(scene, integrator, 33, 17, 8, 7);
}

}  // namespace
}  // namespace glint
