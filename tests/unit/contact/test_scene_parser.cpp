// The scene-file parser on file content (MPI-free; the fuzz target tests/fuzz/fuzz_scene.cpp drives it):
// valid content gives the bodies, every kind of bad input throws SceneError naming the line.
#include "contact/scenes.hpp"

#include <gtest/gtest.h>

using namespace suite::contact;

TEST(ContactSceneParser, ValidContent) {
  auto b = parseScene("# comment\nplane normal=0,0,1\nbox name=b half=0.5,0.5,0.5 pos=0,0,0.5 mass=2\n"
                      "sphere radius=0.25 pos=0,0,2 vel=1,0,0   # trailing comment\n",
                      "t.scene");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_TRUE(b[0].is_static);
  EXPECT_EQ(b[1].name, "b");
  EXPECT_DOUBLE_EQ(b[1].mass, 2.0);
  EXPECT_DOUBLE_EQ(b[2].v.x(), 1.0);
}

TEST(ContactSceneParser, BadContentThrows) {
  auto msg = [](const std::string& text) {
    try {
      parseScene(text, "t.scene");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(msg(""), "scene file t.scene: no bodies");
  EXPECT_NE(msg("torus radius=1\n").find("t.scene:1: unknown body type 'torus'"), std::string::npos);
  EXPECT_NE(msg("plane\nsphere radius=abc\n").find("t.scene:2: bad number 'abc' for radius"),
            std::string::npos);
  EXPECT_NE(msg("box half=1,1\n").find("half needs 3 comma-separated numbers"), std::string::npos);
  EXPECT_NE(msg("sphere radius=1e999\n").find("bad number"), std::string::npos);
  EXPECT_NE(msg("sphere radius=-1\n").find("t.scene:1:"), std::string::npos);
  EXPECT_NE(msg("sphere radius 1\n").find("expected key=value"), std::string::npos);
  EXPECT_NE(msg("sphere radius=1 colour=red\n").find("unknown key 'colour'"), std::string::npos);
  EXPECT_NE(msg("plane normal=0,0,0\n").find("plane normal must be non-zero"), std::string::npos);
  EXPECT_NE(msg(std::string(1000, '\0')).find("unknown body type"), std::string::npos);
}
