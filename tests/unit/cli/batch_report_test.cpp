// Batch mode's progress prefix, durations, folded notes and throughput line (cli/batch_report.h).
#include "cli/batch_report.h"

#include <gtest/gtest.h>

namespace smpl {
namespace {

TEST(BatchReport, ProgressPrefixWithTheTimeLeftOnlyOnATerminal) {
  EXPECT_EQ(batchProgressPrefix(1, 20, 3.0, false), "[1/20] ");
  EXPECT_EQ(batchProgressPrefix(1, 20, 3.0, true), "[1/20, ETA 0:57] ");  // 3 s a file, 19 left
  EXPECT_EQ(batchProgressPrefix(5, 20, 500.0, true), "[5/20, ETA 25:00] ");
  EXPECT_EQ(batchProgressPrefix(20, 20, 60.0, true), "[20/20] ");  // nothing left
}

TEST(BatchReport, DurationsRoundUp) {
  EXPECT_EQ(formatDuration(0), "0:00");
  EXPECT_EQ(formatDuration(0.2), "0:01");
  EXPECT_EQ(formatDuration(61), "1:01");
  EXPECT_EQ(formatDuration(3600 + 62), "1:01:02");
  EXPECT_EQ(formatDuration(-5), "0:00");
}

TEST(BatchReport, TheSameNoteOfManyMotionsIsOneLineWithItsCount) {
  BatchNotes notes(20);
  for (int i = 19; i >= 0; --i) {  // workers finish in any order
    const std::string name = "walk" + std::to_string(i);
    notes.set(i, name, {name + ": the motion has DMPL coefficients, not baked"});
  }
  EXPECT_EQ(notes.folded(),
            std::vector<std::string>{"the motion has DMPL coefficients, not baked (20 motions)"});
}

TEST(BatchReport, NotesOfOneMotionKeepItsNameAndMotionOrder) {
  BatchNotes notes(3);
  notes.set(2, "c", {"c: assumed 30 fps", "shared"});
  notes.set(0, "a", {"a: 2 of 4 joints dropped", "shared", "shared"});  // twice: one motion
  EXPECT_EQ(notes.folded(), (std::vector<std::string>{"a: 2 of 4 joints dropped",
                                                      "shared (2 motions)", "c: assumed 30 fps"}));
}

TEST(BatchReport, NoNotesNoLines) { EXPECT_TRUE(BatchNotes(4).folded().empty()); }

TEST(BatchReport, ThroughputLineGivesMotionsPerSecondAndStageShares) {
  StageSeconds summed;
  summed.read = 1.0;
  summed.fit = 0.5;
  summed.bake = 2.5;
  summed.write = 6.0;
  EXPECT_EQ(batchThroughputLine(20, 4.0, summed),
            "batch: 20 motions in 4.00 s (5.00 motions/s); time in read 10%, fit 5%, bake 25%, "
            "write 60%");
  EXPECT_EQ(batchThroughputLine(1, 0.5, StageSeconds()),
            "batch: 1 motion in 0.50 s (2.00 motions/s); time in read 0%, fit 0%, bake 0%, "
            "write 0%");
  EXPECT_EQ(batchThroughputLine(0, 3.0, summed), "");  // nothing converted: no line
}

}  // namespace
}  // namespace smpl
