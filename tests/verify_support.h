#pragma once
// What `asset-lint verify --output-format json` must answer for the analytic two-finger gripper
// (fixtures/verify/two_finger*, in every format): two 50 g prismatic box fingers 90 mm apart,
// one a mimic of the other, a 0.5 kg box with μ = 0.5 at g = 10. The drive pushes the driven
// finger with F and the mimic constraint carries the other finger's reaction back, so friction
// holds μ·F: the box needs F ≥ m·g/μ = 10 N.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace assetlint::test {

inline const nlohmann::json& verify_scene(const nlohmann::json& report, const std::string& kind, int nth = 0) {
  for (const auto& s : report["scenes"])
    if (s["kind"] == kind && nth-- == 0) return s;
  FAIL("no scene " << kind);
  static nlohmann::json none;
  return none;
}

// At F = 20 N every scene passes; the close takes the stroke over both fingers' speed, 45 mm at
// 0.1 m/s = 0.45 s (the target ramps at the 0.1 m/s max velocity); the boxes are met at 10 % and
// 50 % of the 45 mm stroke and at the guide's 0.01 m: gaps 90 − 2·4.5 = 81 mm, 90 − 2·22.5 = 45 mm
// and 10 mm. The spring is past its 20 N max force at the two wider boxes; at the 10 mm box it
// is k·Δ = 4000 N/m × 5 mm = 20 N less the sub-millimetre penetration.
inline void check_two_finger_holds(const nlohmann::json& report) {
  CHECK(report["passed"] == true);
  REQUIRE(report["scenes"].size() == 8);
  const auto& close = verify_scene(report, "close");
  CHECK(close["object"].is_null());
  CHECK(close["metrics"]["spec_close_time_s"].get<double>() == Approx(0.45));
  CHECK(close["metrics"]["close_time_s"].get<double>() == Approx(0.45).epsilon(0.05));
  CHECK(close["metrics"]["diverged"] == false);
  CHECK(verify_scene(report, "grasp", 0)["object"]["width_m"].get<double>() == Approx(0.081));
  CHECK(verify_scene(report, "grasp", 1)["object"]["width_m"].get<double>() == Approx(0.045));
  CHECK(verify_scene(report, "grasp", 2)["object"]["width_m"].get<double>() == Approx(0.010));
  for (int i = 0; i < 3; ++i) {
    const auto& grasp = verify_scene(report, "grasp", i)["metrics"];
    CHECK(grasp["required_grip_force_n"].get<double>() == Approx(10.0));
    CHECK(grasp["grip_force_n"].get<double>() == Approx(20.0).epsilon(0.05));
    CHECK(grasp["peak_penetration_m"].get<double>() < 0.002);
    CHECK(grasp["mimic_error_max"].get<double>() < 1e-3);
    CHECK(grasp["diverged"] == false);  // its kinetic energy stays far below the drive's 2 × 20 N × 45 mm
    const auto& hold = verify_scene(report, "hold", i)["metrics"];
    CHECK(hold["slip_m"].get<double>() < 0.005);
    CHECK(hold["diverged"] == false);
  }
  CHECK(verify_scene(report, "lift")["passed"] == true);
  CHECK(verify_scene(report, "lift")["metrics"]["slip_m"].get<double>() < 0.005);
}

// At F = 5 N (μ·F = 2.5 N against the box's 5 N weight) the grasps report 5 N of grip and fail on
// it, and every hold and the lift slip out.
inline void check_two_finger_slips(const nlohmann::json& report) {
  CHECK(report["passed"] == false);
  for (int i = 0; i < 3; ++i) {
    const auto& hold = verify_scene(report, "hold", i);
    CHECK(hold["passed"] == false);
    CHECK(hold["metrics"]["slip_m"].get<double>() > 0.005);
    const auto& grasp = verify_scene(report, "grasp", i);
    CHECK(grasp["metrics"]["grip_force_n"].get<double>() == Approx(5.0).epsilon(0.05));
    CHECK(grasp["failures"][0].get<std::string>().find("grip force") != std::string::npos);
  }
  CHECK(verify_scene(report, "lift")["passed"] == false);
}

}  // namespace assetlint::test
