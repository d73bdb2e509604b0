// The offscreen renderer: camera geometry in closed form, pixels where the projection puts them,
// PNG round trips, determinism, and the console's snapshot/video commands.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <unistd.h>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"
#include "simulator/render/camera.hpp"
#include "simulator/render/png_file.hpp"
#include "simulator/render/snapshot.hpp"
#include "simulator/render/views.hpp"
#include "simulator/render/world_renderer.hpp"
#include "simulator/world/ode/ode_world.hpp"
#include "simulator/world/physics_world.hpp"
#include "tests/error_text.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride::render {
namespace {

namespace fs = std::filesystem;

fs::path temp(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("stride_render_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

using stride::test_support::error_of;

TEST(Camera, TargetProjectsToTheImageCentreAndTheFovToTheEdges) {
  CameraView c;
  c.eye = {2, 0, 1};
  c.target = {0, 0, 1};
  c.fov = 0.8;
  c.width = 640;
  c.height = 480;
  const auto centre = project_to_pixel(c, c.target);
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x(), 320, 1e-9);
  EXPECT_NEAR(centre->y(), 240, 1e-9);
  // A point fov/2 above the axis lands on the top edge; the horizontal fov follows the aspect.
  const auto top = project_to_pixel(c, {0, 0, 1 + 2 * std::tan(0.4)});
  EXPECT_NEAR(top->y(), 0, 1e-9);
  const double half_width = 2 * std::tan(0.4) * 640.0 / 480.0;
  // Looking along -x, world +y is the image's right.
  EXPECT_NEAR(project_to_pixel(c, {0, half_width, 1})->x(), 640, 1e-9);
  EXPECT_FALSE(project_to_pixel(c, {3, 0, 1}));  // behind the eye
}

const char* kBoxScene = R"(<scene name="box">
  <ground/>
  <box name="block" size="0.2 0.2 0.2" xyz="0 0 0.1"/>
  <camera name="cam" xyz="1 0 0.1" look_at="0 0 0.1" fov="50deg" width="320" height="240"/>
</scene>)";

bool is_box_colour(const std::uint8_t* p) {
  return p[0] > p[2] + 20 && p[1] > p[2];
}

TEST(WorldRenderer, ABoxAppearsWhereTheCameraProjectsIt) {
  auto sim = test::scene_from_text(kBoxScene);
  const CameraView view = resolve_view(*sim, "cam");
  WorldRenderer renderer;
  const RgbaImage img = renderer.render(sim->world(), view, sim->scene().lights);
  ASSERT_EQ(img.width, 320);
  ASSERT_EQ(img.height, 240);
  // The front face spans y = +-0.1 at x = 0.1: scan the centre row for box-coloured pixels.
  const int row = 120;
  int first = -1, last = -1;
  for (int x = 0; x < img.width; ++x)
    if (is_box_colour(img.pixel(x, row))) {
      if (first < 0) first = x;
      last = x;
    }
  const double left = project_to_pixel(view, {0.1, -0.1, 0.1})->x();
  const double right = project_to_pixel(view, {0.1, 0.1, 0.1})->x();
  EXPECT_NEAR(first, left, 1.5);
  EXPECT_NEAR(last + 1, right, 1.5);
  // Sky above the horizon is the clear colour; the floor below the box is not box-coloured.
  const std::uint8_t* sky = img.pixel(160, 2);
  EXPECT_EQ(sky[0], 158);
  EXPECT_EQ(sky[1], 189);
  EXPECT_EQ(sky[2], 219);
  EXPECT_FALSE(is_box_colour(img.pixel(160, 235)));
}

TEST(WorldRenderer, SamePicturesFromTheSameStateAndAFreshRenderer) {
  auto sim = test::scene_from_text(kBoxScene);
  const CameraView view = resolve_view(*sim, "cam");
  WorldRenderer a, b;
  const RgbaImage first = a.render(sim->world(), view, {});
  EXPECT_EQ(first.rgba, a.render(sim->world(), view, {}).rgba);
  EXPECT_EQ(first.rgba, b.render(sim->world(), view, {}).rgba);
}

TEST(WorldRenderer, TheStandingNaoFillsItsProjectedHeight) {
  auto scene = sim::parse_scene_file(test::source_path("scenes/nao_stand.xml"));
  sim::Simulation with_robot(scene);
  scene.robots.clear();
  sim::Simulation empty(scene);
  CameraView view = resolve_view(with_robot, "front");
  WorldRenderer renderer;
  const RgbaImage a = renderer.render(with_robot.world(), view, {});
  const RgbaImage b = renderer.render(empty.world(), view, {});
  int top = a.height, bottom = -1, changed = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (std::memcmp(a.pixel(x, y), b.pixel(x, y), 4) != 0) {
        ++changed;
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
  ASSERT_GT(changed, 1000);
  // The drawn extent is bracketed by the projections of the collision geometry's bounding
  // boxes: the lowest pixel is the front bottom edge of the soles, the highest the head's top.
  double bottom_px = 0, top_near = 1e9, top_far = 1e9;
  const dSpaceID space = dynamic_cast<const sim::OdeWorld&>(with_robot.world()).robot_space();
  for (int i = 0; i < dSpaceGetNumGeoms(space); ++i) {
    dReal bb[6];
    dGeomGetAABB(dSpaceGetGeom(space, i), bb);
    const double y = (bb[2] + bb[3]) / 2;
    bottom_px = std::max(bottom_px, project_to_pixel(view, {bb[1], y, bb[4]})->y());
    top_near = std::min(top_near, project_to_pixel(view, {bb[1], y, bb[5]})->y());
    top_far = std::min(top_far, project_to_pixel(view, {bb[0], y, bb[5]})->y());
  }
  EXPECT_NEAR(bottom + 1, bottom_px, 2.0);
  EXPECT_GE(top, std::min(top_near, top_far) - 2);
  EXPECT_LE(top, std::max(top_near, top_far) + 2);
}

TEST(PngFile, RoundTripAndErrorsNameTheFile) {
  RgbaImage img;
  img.width = 3;
  img.height = 2;
  for (int i = 0; i < 24; ++i) img.rgba.push_back(static_cast<std::uint8_t>(i * 10));
  const std::string path = temp("round.png").string();
  write_png(path, img);
  const RgbaImage back = read_png(path);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.rgba, img.rgba);
  write_png(path, img, PngEncoding::Fast);  // a movie frame's encoding: as lossless
  EXPECT_EQ(read_png(path).rgba, img.rgba);
  EXPECT_NE(error_of([] { read_png("/nonexistent/x.png"); }).find("'/nonexistent/x.png'"),
            std::string::npos);
  EXPECT_EQ(error_of([&] { write_png("/nonexistent/dir/x.png", img); }),
            "cannot write '/nonexistent/dir/x.png': No such file or directory");
  EXPECT_EQ(error_of([&] { write_png("/dev/full", img); }),
            "cannot write '/dev/full': No space left on device");
}

TEST(SceneCamera, BadAttributesNameFileLineAndExpectation) {
  const auto parse = [](const std::string& camera) {
    return error_of([&] {
      sim::parse_scene_text("<scene name=\"s\">\n" + camera + "\n</scene>",
                            test::source_path("tests/data/cam.xml"));
    });
  };
  EXPECT_NE(parse(R"(<camera name="c" fov="200deg"/>)").find("cam.xml:2"), std::string::npos);
  EXPECT_NE(parse(R"(<camera name="c" fov="200deg"/>)").find("fov"), std::string::npos);
  EXPECT_NE(parse(R"(<camera xyz="1 0 0"/>)").find("name"), std::string::npos);
  EXPECT_NE(parse(R"(<camera name="c" xyz="1 1 1" look_at="1 1 1"/>)").find("look_at"),
            std::string::npos);
  EXPECT_NE(parse("<camera name=\"c\"/>\n<camera name=\"c\"/>").find("exists already"),
            std::string::npos);
  EXPECT_NE(parse(R"(<light direction="0 0 0"/>)").find("direction"), std::string::npos);
  EXPECT_NE(parse(R"(<camera name="c" width="10"/>)").find("width"), std::string::npos);
}

TEST(ConsoleSnapshot, WritesPicturesAndVideoFramesAndRejectsBadInput) {
  console::LocalTarget target;
  std::ostringstream out;
  console::Interpreter con(target, out);
  con.execute("load " + test::source_path("scenes/nao_stand.xml"));
  const std::string png = temp("front.png").string();
  con.execute("snapshot " + png + " front");
  const RgbaImage img = read_png(png);
  EXPECT_EQ(img.width, 640);
  EXPECT_EQ(img.height, 480);

  const std::string bad_view = error_of([&] { con.execute("snapshot " + png + " nosuch"); });
  EXPECT_NE(bad_view.find("unknown view 'nosuch' (expected one of: follow, front, side, top)"),
            std::string::npos)
      << bad_view;
  EXPECT_NE(error_of([&] { con.execute("snapshot picture.txt"); }).find(".png"), std::string::npos);

  const fs::path frames = temp("frames");
  fs::remove_all(frames);
  con.execute("video start " + frames.string() + " side fps 50");
  con.execute("run 0.1");  // 100 steps of 1 ms at 50 fps: a frame every 20 steps
  out.str("");
  con.execute("video stop");
  EXPECT_EQ(out.str(), "video: 5 frames\n");
  int files = 0;
  for (const auto& e : fs::directory_iterator(frames)) files += e.path().extension() == ".png";
  EXPECT_EQ(files, 5);
  EXPECT_TRUE(fs::exists(frames / "frame_000004.png"));
  con.execute("run 0.05");  // stopped: no more frames
  EXPECT_FALSE(fs::exists(frames / "frame_000005.png"));
  EXPECT_NE(error_of([&] { con.execute("video start"); }).find("directory"), std::string::npos);
  EXPECT_NE(error_of([&] { con.execute("video start d fps 0"); }).find("fps"), std::string::npos);
}

}  // namespace
}  // namespace stride::render
