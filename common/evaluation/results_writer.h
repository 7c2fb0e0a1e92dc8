#pragma once
// Writes one mission's results folder: machine-readable JSON/CSV and the team's reconstruction
// (map.ply, map.pcd, map.bt). Its figures are drawn from these files by tools/report/run_report.py.

#include <string>
#include <vector>

#include "common/evaluation/experiment_record.h"

namespace hexplore::evaluation {

// Creates `dir` if needed and writes summary.json, completeness.csv, trajectories.csv,
// communication.csv, map_transmission.csv, planning.csv, open_targets.csv and the map files
// (evaluation/map_export.h). Returns the files written.
// Throws std::runtime_error naming the file that could not be written.
std::vector<std::string> write_results(const ExperimentRecord& record, const std::string& dir);

// The summary object alone (also embedded in summary.json), as JSON text.
std::string summary_json(const ExperimentRecord& record);

// Mean, standard deviation, min and max over several missions (e.g. several seeds) of the
// headline metrics, as JSON text: exploration time, final completeness (team and observable),
// accumulated completeness, trajectory length, planning time, team KB/s, wall time; plus the
// seeds and each run's end reason.
std::string multi_run_summary_json(const std::vector<ExperimentRecord>& runs);

}  // namespace hexplore::evaluation
