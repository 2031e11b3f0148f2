#pragma once
/// One destruction run as a grid keeps it: its timings and its record of named figures (a sample),
/// and its accuracy figures folded into its cell's worst.

#include "harness/pipeline/destruction_run.h"
#include "harness/results/grid_record.h"

#include <functional>

namespace shatter {

/// Adds figures of a caller's own to the record of each run (`record.add(spec, value)`), after the
/// known ones: they reach every output that their spec names, with no other edit.
using ExtraFigures = std::function<void(const RunResult& run, FigureRecord& record)>;

/// The record of named figures of `run` (run_figures.h, in that order), then what `extra` adds.
FigureRecord run_record(const RunResult& run, const ExtraFigures& extra = {});

/// The sample of `run`: its timings and run_record(run, extra). Calibration is left 0.
GridSample run_sample(const RunResult& run, const ExtraFigures& extra = {});

/// Folds the accuracy figures of `run` into its cell's worst, `first` for the cell's first repetition.
void add_run_accuracy(CellAccuracy& into, const RunResult& run, bool first);

}  // namespace shatter
