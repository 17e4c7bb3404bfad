#pragma once
// The matched posture as a controller FRAME (a shifted and rotated workpiece coordinate system),
// besides the machine-axis adjustments of machine.h. Plain C++, no Qt.
//
// INPUT. The posture p = R q + t (docs/file-formats.md#match-result): a nominal point q of the program
// lies at R q + t in the coordinates of the current work offset (G54 / active preset / settable
// frame), mm. The frame written below makes the control take the program's coordinates q in a
// coordinate system whose origin is t and whose axes are the columns of R, so the program runs on
// the workpiece where it actually lies. R must be a rotation (det +1, orthonormal); the isotropic
// scale of an --allow-scale fit is NOT applied (no frame below scales).
//
// ANGLES. Every control below takes positive angles by the right-hand rule (counter-clockwise
// looking from the positive axis towards the origin). Angles are written in degrees.
//  * HEIDENHAIN PLANE SPATIAL SPA SPB SPC: "spatial angles define a working plane through up to three
//    rotations" about the NON-TILTED axes "A, then B, then C" (TNC 620 / iTNC 530 user's manuals,
//    "Defining the working plane with the spatial angle: PLANE SPATIAL"), i.e.
//        R = Rz(SPC) Ry(SPB) Rx(SPA).
//    Written SPB in [-90, 90]; at SPB = +-90 (gimbal lock: only SPA -+ SPC is defined) SPC = 0.
//  * SINUMERIK: one AROT per block, Z then Y then X. AROT rotates the CURRENT frame additively about
//    its own (already rotated) axes, so Z, Y', X'' gives the same R = Rz(c) Ry(b) Rx(a), independent of
//    machine data MD 10600 $MN_FRAME_ANGLE_INPUT_MODE (which only orders the angles of one ROT block).
//  * FANUC G68.2 X Y Z I J K (tilted working plane command, Euler angles): the feature coordinate
//    system is turned by I about Z, then by J about the NEW X, then by K about the NEW Z:
//        R = Rz(I) Rx(J) Rz(K).
//    Written J in [0, 180]; at J = 0 or 180 (gimbal lock: only I +- K is defined) I = 0.
//
// OFFSETS. The origin t is written as
//  * HEIDENHAIN: CYCL DEF 7 DATUM SHIFT (7.1 X, 7.2 Y, 7.3 Z) BEFORE the PLANE block, so the plane
//    tilts about the shifted datum. PLANE ... STAY: the control computes the rotary-axis positions
//    but does not move them (position them in a later block, or replace STAY by MOVE / TURN).
//    Written as a complete program (FrameOptions::programName, default METROFIT_FRAME) to CALL PGM from the
//    part program after the preset is active; datum shift and tilted plane stay active after the call (reset
//    with PLANE RESET STAY and CYCL DEF 7 with X+0 Y+0 Z+0).
//  * SINUMERIK: TRANS X= Y= Z= (programmable frame, on top of the active settable frame G54 ...),
//    then the three AROT blocks; a subprogram ending with M17. The programmable frame stays
//    active after the return; TRANS without values resets it. Orienting the tool needs CYCLE800
//    (swivel data record of the machine) or TRAORI: the frame alone rotates coordinates only.
//  * FANUC: G68.2 X Y Z (the feature coordinate system's origin in the current workpiece coordinate
//    system) in a subprogram ending with M99, called after the work offset is selected. Cancel with
//    G69. G53.1 (tool axis direction control) is NOT written: it moves the rotary axes; program it at
//    a safe position. The program number follows setup/export.h (outside O8000-O9999 by default).
//
// DECIMALS. FrameOptions::decimals for mm and degrees alike (default 4; FANUC IS-B takes 3).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace metrofit::machine {

enum class FrameFormat { Heidenhain, Siemens, Fanuc };

/// "heidenhain", "siemens", "fanuc".
std::vector<std::string> frameFormatNames();
/// OptionsError naming `field` and the known names when `name` is unknown.
FrameFormat parseFrameFormat(const std::string& name, const std::string& field);
const char* toString(FrameFormat f);

/// {SPA, SPB, SPC} in degrees with R = Rz(SPC) Ry(SPB) Rx(SPA), SPB in [-90, 90] (see above).
std::array<double, 3> spatialAnglesDeg(const Eigen::Matrix3d& R);
/// {I, J, K} in degrees with R = Rz(I) Rx(J) Rz(K), J in [0, 180] (see above).
std::array<double, 3> eulerZxzAnglesDeg(const Eigen::Matrix3d& R);

struct FrameOptions {
  int decimals = 4;          ///< 0..12
  int programNumber = 7101;  ///< FANUC O-number (1..7999, see setup/export.h)
  /// HEIDENHAIN program name of BEGIN PGM / END PGM: the file's name without its extension (the control
  /// lists the program under its file name). Letters, digits, '_' and '-', at most 32 characters.
  std::string programName = "METROFIT_FRAME";
  std::string title;  ///< first comment line

  bool isValid(std::string* why) const;
};

/// The HEIDENHAIN program name of a frame written to `file` (the control lists a program under its file
/// name): the file's name without its extension, every character other than a letter, digit, '_' or '-'
/// replaced by '_', cut to 32 characters; FrameOptions{}.programName when nothing is left. The CLI
/// (match --frame-out) and the GUI's "Save frame" name the program so.
std::string frameProgramName(const std::string& file);

/// The frame for posture (R, t) in the control's language (see above). ValidationError when R is not
/// a rotation or a value is not finite.
/// Only the blocks that set the frame (no program frame, comments or block numbers), as written by
/// writeControllerFrame: HEIDENHAIN CYCL DEF 7.0-7.3 and PLANE SPATIAL ... STAY, SINUMERIK TRANS and
/// AROT Z/Y/X, FANUC G68.2. Same checks as writeControllerFrame.
std::vector<std::string> controllerFrameBlocks(const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                                               FrameFormat format, int decimals = 4);
std::string writeControllerFrame(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, FrameFormat format,
                                 const FrameOptions& options = {});

}  // namespace metrofit::machine
