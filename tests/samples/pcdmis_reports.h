// A PC-DMIS text report shared by the tests that read one (core/setup/cmm_text_report_test,
// widgets/datasetview_test). Written from the format's own documentation, not from any Metrofit
// writer: Hexagon, PC-DMIS 2019 R1 help, "Dimension Command Format" (the DIM line, GRAPH/TEXT/MULT/
// OUTPUT, the columns AX NOMINAL +TOL -TOL MEAS DEV OUTTOL, "END OF DIMENSION name"), and PC-DMIS
// 2021.2 help, "To Dimension a Feature Using the LOCATION Option" (CIRCLE = X, Y, D; PLANE = its
// axis). The full citations are at the top of tests/core/setup/cmm_text_report_test.cpp.
#pragma once

namespace metrofit::test {

// Part BRACKET: circle CIR1 (X, Y in tolerance, D 18.520 against 18.500 +0.030/-0.050) and plane
// PLN1 (Z 42.035 against 42.000 +-0.020: out of tolerance by 0.015).
inline constexpr const char* kPcDmisBracketReport =
    "PART NAME  : BRACKET\n"
    "REV NUMBER : A\n"
    "SER NUMBER : 0042\n"
    "STATS COUNT : 1\n"
    "\n"
    "DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=MM ,$\n"
    "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
    "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
    "X      25.000      0.050      0.050     25.012      0.012      0.000 ----#----\n"
    "Y      40.000      0.050      0.050     39.996     -0.004      0.000 ----#----\n"
    "D      18.500      0.030      0.050     18.520      0.020      0.000 -------#-\n"
    "END OF DIMENSION LOC1\n"
    "\n"
    "DIM LOC2= LOCATION OF PLANE PLN1  UNITS=MM ,$\n"
    "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
    "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
    "Z      42.000      0.020      0.020     42.035      0.035      0.015 --------->\n"
    "END OF DIMENSION LOC2\n";

}  // namespace metrofit::test
