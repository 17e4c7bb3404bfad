#pragma once
// metrofit-bench --thermal and --real-thermal (targets for the models of Abdulshahed 2016, grey neural
// network thermal model):
//  --thermal       GNNMCI(1,N) training time on a 4-hour log at 1-minute sampling (the simulated
//                  spindle test, 241 rows, T1..T4) against the MLP's Levenberg-Marquardt training and
//                  GMC(1,N)'s least squares on the same rows in the same run (ratios); the modular case
//                  (Z + C heating tests -> combined test) with the three models: error reduction and
//                  the Table 4 ordering as measured.
//  --real-thermal  the bundled CAIVIAC log and the SJTU spindle log (../shared/data/real, read in place,
//                  never copied): fit on the first half, predict the second, all three models' Table 4
//                  metrics; then Table 4 for CAIVIAC ch1, ch3, ch5 with every model (gnnmci, gmc, mlp,
//                  linear, lag, dlag, auto) on t5, t9 and on t5, t9, spindle_rpm.
#include <nlohmann/json.hpp>
#include <string>

namespace metrofit::bench {

/// `demoDataDir`: resources/demo/data (the modular tests are read from there when present, else
/// simulated with the demo's seed).
nlohmann::json benchThermal(const std::string& demoDataDir, int repeat);

/// `caiviacCsv`: the bundled log; `sjtuCsv`: thermal_expansion_error_original.csv (skipped with a
/// note when missing).
nlohmann::json benchRealThermal(const std::string& caiviacCsv, const std::string& sjtuCsv);

}  // namespace metrofit::bench
