#pragma once
// The paper's statements as a table a machine can read. Each scene's check
// (scene_checks.hpp) becomes rows of (figure, statement, measure); a case driver writes its
// rows to paper_checks.csv in the run's folder, and scripts/paper_report.py gathers the
// scenes' files into the repository's table of the paper's statements (docs/paper_checks.csv,
// docs/paper.md). A statement is met when every one of its rows is. Host-only.
#include <string>
#include <vector>

#include "analysis/paper_measure.hpp"
#include "analysis/scene_checks.hpp"

namespace rouleau {

// The run's folder's file of the paper's checks.
inline constexpr const char* paper_checks_name = "paper_checks.csv";

struct PaperCheckRow {
  std::string figure;     // "Fig. 9"
  std::string statement;  // the paper's statement, in words
  PaperMeasure measure;
};

// Fig. 6 (two cells aggregate): the final gap < 1.5 r0 and its range over the run's last
// quarter < 0.2 r0. Without the interaction the run is the scene's control, not the
// paper's statement: no rows.
std::vector<PaperCheckRow> paper_rows(const AggregationCheck& check, double zero_force_length, bool interaction);

// Fig. 7 (the interaction acts mainly at the rims): the rims' smallest share of the force
// and their force per area over that elsewhere. A run without interaction forces has no
// rows.
std::vector<PaperCheckRow> paper_rows(const RimInteractionCheck& check, bool forces_acted);

// Figs. 8-12: the strain against the paper's, then each measure of the statement.
std::vector<PaperCheckRow> paper_rows(const StackStatement& statement);

// Fig. 14 (normal cells pass the throat): each normal cell's centroid beyond the throat's
// exit at the end. Fig. 15 (sickle cells block its entrance): each sickle cell not past the
// exit, its front within blocked_front_distance of the entry, its late speed below
// stalled_speed_fraction of its early speed. Only the kinds the run holds have rows.
std::vector<PaperCheckRow> paper_rows(const ContractionPassageCheck& check, const std::vector<std::string>& kinds,
                                      double throat_exit);

// Fig. 14 after the throat: each normal cell's diffuser speed over its throat speed below
// slower_fraction, and with two or more normal cells their neighbour spacing when the last
// has passed over the initial one below closer_fraction.
std::vector<PaperCheckRow> paper_rows(const ContractionOutletCheck& check);

// Fig. 16 (inside, the capsule is longer than its free diameter) and Fig. 17 (the driving
// pressure rises while the capsule enters and falls after it leaves), for a capillary from
// x = `entry` to `exit` [μm].
std::vector<PaperCheckRow> paper_rows(const CapillaryPassageCheck& check, double entry, double exit);

// The rows as CSV: a header "figure,statement,metric,value,relation,threshold,unit,met",
// then one line per row (met as 1 or 0; text fields quoted, quotes doubled).
std::string paper_checks_csv(const std::vector<PaperCheckRow>& rows);

// Writes the rows to RUN_DIR/paper_checks.csv atomically (io/atomic_file.hpp).
void write_paper_checks(const std::string& run_dir, const std::vector<PaperCheckRow>& rows);

}  // namespace rouleau
