// check_resumed_config: the option-by-option comparison --resume makes between a file's
// /provenance/config and the resuming run's effective config (resume_check.hpp).
#include <gtest/gtest.h>

#include <string>

#include "rocksweep/app/resume_check.hpp"
#include "rocksweep/core/errors.hpp"

using namespace rocksweep;

namespace {

const std::string kStored =
    "mass = 3361.0\nfriction-coefficient = 0.5\nanchorages = [\"free\", \"constant\"]\nmethod = \"events\"\n"
    "lanes = 8\nsweep.chunk = 512\nsweep.pulse = \"one-sine\"\nmerge.parts = [\"p1.h5\", \"p2.h5\"]\n";

/// The message check_resumed_config throws for `now`, or "" if it accepts it.
std::string refusal(const std::string& now, const std::string& stored = kStored) {
    try {
        check_resumed_config("f.h5", stored, now);
    } catch (const InputError& e) {
        return cli_message(e);
    }
    return "";
}

}  // namespace

TEST(ResumeCheck, TheSameOptionsResume) {
    EXPECT_EQ(refusal(kStored), "");
    // Numbers compare as numbers; a command's table is not part of the option; what changes no
    // result (lanes, chunk) and merge's parts may differ or be absent.
    EXPECT_EQ(refusal("mass = 3361\nfriction-coefficient = 5e-1\nanchorages = [\"free\", \"constant\"]\n"
                      "method = \"events\"\nlanes = 4\nmerge.pulse = \"one-sine\"\n"),
              "");
}

TEST(ResumeCheck, AnotherValueIsRefusedNamingBoth) {
    const std::string tail = ", as f.h5 was computed with (--resume continues a file only with the settings that shaped its results)";
    EXPECT_EQ(refusal("mass = 3361\nfriction-coefficient = 0.6\nanchorages = [\"free\", \"constant\"]\nmethod = \"events\"\n"
                      "sweep.pulse = \"one-sine\"\n"),
              "--friction-coefficient = 0.6 is invalid: 0.5" + tail);
    EXPECT_EQ(refusal("mass = 3361\nfriction-coefficient = 0.5\nanchorages = [\"free\"]\nmethod = \"events\"\n"
                      "sweep.pulse = \"one-sine\"\n"),
              "--anchorages = free is invalid: free constant" + tail);
    EXPECT_EQ(refusal("mass = 3361\nfriction-coefficient = 0.5\nanchorages = [\"free\", \"constant\"]\nmethod = \"events\"\n"
                      "sweep.pulse = \"ricker\"\n"),
              "--pulse = ricker is invalid: one-sine" + tail);
}

TEST(ResumeCheck, AnOptionInOneConfigOnlyIsNotGivenInTheOther) {
    const std::string tail = ", as f.h5 was computed with (--resume continues a file only with the settings that shaped its results)";
    EXPECT_EQ(refusal(kStored + "no-energy-stop = true\n"), "--no-energy-stop = given is invalid: not given" + tail);
    EXPECT_EQ(refusal("friction-coefficient = 0.5\nanchorages = [\"free\", \"constant\"]\nmethod = \"events\"\n"
                      "sweep.pulse = \"one-sine\"\n"),
              "--mass = not given is invalid: 3361.0" + tail);
}

TEST(ResumeCheck, AFileWithoutAConfigIsNotChecked) { EXPECT_EQ(refusal("mass = 1\n", ""), ""); }

TEST(ResumeCheck, FloorsAndSaAreLeftToTheSuiteFilesCanonicalAttributes) {
    // The suite file compares its floors parsed and its Sa oscillator exactly (floor_suite.sh):
    // a floor spelt otherwise is the same floor, and another is refused there, naming it once.
    const std::string was = kStored + "suite.floor = [\"f2: 0.5 0.05 1.3\"]\nsuite.sa-period = 0.5\nsuite.sa-damping = 0.05\n";
    EXPECT_EQ(refusal(kStored + "suite.floor = [\"f2: 0.50 0.05 1.30\"]\nsuite.sa-period = 0.5\n", was), "");
}

// A design frees only what cuts up the work: no attribute of its files checks the refinement, so
// its options do (design_resume.sh resumes a design with another --refine).
TEST(ResumeCheck, ADesignMayChangeOnlyHowTheWorkIsCutUp) {
    const std::string stored = "mass = 3361.0\ndesign.refine = 4\ndesign.chunk = 64\n";
    const auto design = [&](const std::string& now) {
        try {
            check_resumed_config("r.h5", stored, now, work_options());
        } catch (const InputError& e) {
            return cli_message(e);
        }
        return std::string();
    };
    EXPECT_EQ(design("mass = 3361\ndesign.refine = 4.0\ndesign.chunk = 7\nlanes = 4\ncheckpoint-interval = 3\n"), "");
    EXPECT_EQ(design("mass = 3361.0\ndesign.refine = 2\n"),
              "--refine = 2 is invalid: 4, as r.h5 was computed with (--resume continues a file only with the settings that "
              "shaped its results)");
    EXPECT_EQ(refusal("mass = 3361.0\ndesign.refine = 2\n", stored), "");  // a sweep's file checks it by its attributes
}

// What every --resume compares: the stored effective config, key by key.
TEST(ResumeCheck, ReadsTheKeysOfAnEffectiveConfig) {
    const auto v = config_values("# comment\nmass = 3361.0\nanchorages = [\"free\", \"constant\"]\n[design]\ndesign.refine = 4\n");
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v.at("mass"), "3361.0");
    EXPECT_EQ(v.at("anchorages"), "[\"free\", \"constant\"]");
    EXPECT_EQ(v.at("design.refine"), "4");
}
