// SPDX-License-Identifier: MIT
// The BVH reader on hostile text: inputs found by tests/fuzz/fuzz_bvh_reader, and their kin. Each
// once hit undefined behaviour or allocated without bound; each must now give a message.
#include "export/bvh_reader.h"
#include "test_support.h"

namespace {

// A one-joint hierarchy with `channels` and the MOTION section `motion`.
std::string Bvh(const std::string& channels, const std::string& motion) {
  return "HIERARCHY\nROOT hips\n{\n  OFFSET 0 1 0\n" + channels + "}\nMOTION\n" + motion;
}

std::string ErrorOf(const std::string& text) {
  rise::BvhMotion motion;
  return rise::ParseBvh(text, {}, "in.bvh", motion);
}

}  // namespace

TEST_SUITE("bvh_reader") {
  TEST_CASE("fuzz crash: a frame count beyond any integer is refused, not cast") {
    // fuzz_bvh_reader's first crash: "Frames: 41e39" was cast to size_t (UBSan
    // float-cast-overflow), then used to size the frame list.
    CHECK(ErrorOf(Bvh("", "Frames: 41e39\nFrame Time: 0.0333333\n")) ==
          "cannot read BVH 'in.bvh': MOTION needs 'Frames: <count>'");
    CHECK(ErrorOf(Bvh("", "Frames: nan\nFrame Time: 0.0333333\n")) ==
          "cannot read BVH 'in.bvh': MOTION needs 'Frames: <count>'");
    CHECK(ErrorOf(Bvh("", "Frames: 2.5\nFrame Time: 0.0333333\n")) ==
          "cannot read BVH 'in.bvh': MOTION needs 'Frames: <count>'");
  }
  TEST_CASE("a frame count larger than the values present allocates nothing for it") {
    // 1e30 frames of one channel would need 1e30 positions; the values are counted first.
    CHECK(ErrorOf(Bvh("  CHANNELS 1 Yposition\n", "Frames: 1e30\nFrame Time: 0.1\n1.5\n")) ==
          "cannot read BVH 'in.bvh': MOTION holds fewer values than Frames x channels");
    // Without channels no value bounds the count, so frames need channels.
    CHECK(ErrorOf(Bvh("", "Frames: 1e9\nFrame Time: 0.1\n")) ==
          "cannot read BVH 'in.bvh': MOTION has frames but no joint has CHANNELS");
    rise::BvhMotion motion;
    CHECK(rise::ParseBvh(Bvh("", "Frames: 0\nFrame Time: 0.1\n"), {}, "in.bvh", motion) == "");
    CHECK(motion.FrameCount() == 0);
  }
  TEST_CASE("channel counts, offsets and values a float cannot hold are refused") {
    CHECK(ErrorOf(Bvh("  CHANNELS nan\n", "Frames: 0\nFrame Time: 0.1\n")) ==
          "cannot read BVH 'in.bvh': CHANNELS needs a count from 0 to 6");
    CHECK(ErrorOf(Bvh("  CHANNELS 1.5 Yposition\n", "Frames: 0\nFrame Time: 0.1\n")) ==
          "cannot read BVH 'in.bvh': CHANNELS needs a count from 0 to 6");
    CHECK(ErrorOf("HIERARCHY\nROOT hips\n{\n  OFFSET 0 1e39 0\n}\nMOTION\nFrames: 0\nFrame Time: 0.1\n") ==
          "cannot read BVH 'in.bvh': an OFFSET needs three numbers");
    for (const char* value : {"1e39", "inf", "-nan"}) {
      CAPTURE(value);
      CHECK(ErrorOf(Bvh("  CHANNELS 1 Yposition\n", std::string("Frames: 1\nFrame Time: 0.1\n") + value + "\n")) ==
            "cannot read BVH 'in.bvh': MOTION holds a value that is not a number a float can hold");
    }
    rise::BvhMotion motion;
    REQUIRE(rise::ParseBvh(Bvh("  CHANNELS 1 Yposition\n", "Frames: 1\nFrame Time: 0.1\n3.4e38\n"), {}, "in.bvh",
                           motion) == "");
    CHECK(motion.positions[0][0].y == doctest::Approx(3.4e38));
  }
}
