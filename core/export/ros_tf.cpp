#include "core/export/ros_tf.h"

#include <cmath>
#include <numbers>

#include "core/export/cdr_writer.h"

namespace ydscope {
namespace {

using Matrix = double[2][2];

void multiply(const Matrix& a, const Matrix& b, Matrix& out) {
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) out[r][c] = a[r][0] * b[0][c] + a[r][1] * b[1][c];
}

// The laser frame of `frame` (its reversion and inverted) into the pose's laser frame (the
// official driver's defaults, core/frame/pose.h): Q o(a) = s(a) for every device angle a, where
// o(a) is where the angle lands in /scan and s(a) in the pose's frame; two angles fix it.
void options_to_pose_frame(const RosFrameOptions& frame, Matrix& q) {
  const LapPoint at0{0.0f, 1.0f, PointFlag::None};
  const LapPoint at90{90.0f, 1.0f, PointFlag::None};
  const CommonPoint s0 = laser_point(at0);
  const CommonPoint s90 = laser_point(at90);
  const Matrix s = {{s0.x_mm, s90.x_mm}, {s0.y_mm, s90.y_mm}};
  const double o0 = ros_angle_rad(0.0f, frame);
  const double o90 = ros_angle_rad(90.0f, frame);
  // O is orthogonal (o0 and o90 are a quarter turn apart), so its inverse is its transpose.
  const Matrix o_inverse = {{std::cos(o0), std::sin(o0)}, {std::cos(o90), std::sin(o90)}};
  multiply(s, o_inverse, q);
}

}  // namespace

RosTransform ros_transform_of(const Pose& pose, const RosFrameOptions& frame, std::string parent, std::string child) {
  Matrix q;
  options_to_pose_frame(frame, q);
  const double yaw = pose.yaw_deg * std::numbers::pi / 180.0;
  const Matrix turn = {{std::cos(yaw), -std::sin(yaw)}, {std::sin(yaw), std::cos(yaw)}};
  const Matrix mirror = {{1, 0}, {0, pose.upside_down ? -1.0 : 1.0}};
  // The unit's angle offset adds to its clockwise angles: a turn by -offset in the laser frame.
  const double offset = pose.angle_offset_deg * std::numbers::pi / 180.0;
  const Matrix unturn = {{std::cos(offset), std::sin(offset)}, {-std::sin(offset), std::cos(offset)}};
  // parent = turn * mirror * unturn * q * child + shift (Pose::to_common after q).
  Matrix a, b, linear;
  multiply(turn, mirror, a);
  multiply(a, unturn, b);
  multiply(b, q, linear);

  RosTransform t;
  t.parent_frame = std::move(parent);
  t.child_frame = std::move(child);
  t.translation[0] = pose.x_m;
  t.translation[1] = pose.y_m;
  // linear = R(phi), or R(phi) * diag(1, -1) when it mirrors (a roll of 180 degrees).
  const double phi = std::atan2(linear[1][0], linear[0][0]);
  const bool mirrored = linear[0][0] * linear[1][1] - linear[0][1] * linear[1][0] < 0;
  if (mirrored) {  // q_z(phi) * q_x(pi)
    t.rotation[0] = std::cos(phi / 2);
    t.rotation[1] = std::sin(phi / 2);
    t.rotation[2] = 0;
    t.rotation[3] = 0;
  } else {
    t.rotation[0] = 0;
    t.rotation[1] = 0;
    t.rotation[2] = std::sin(phi / 2);
    t.rotation[3] = std::cos(phi / 2);
  }
  return t;
}

RosTransform ros_unit_transform(const RosFrameOptions& frame, const std::string& laser_frame) {
  // Columns: where the unit's 0 and 90 degrees point in the laser frame, and their cross product.
  const double a0 = ros_angle_rad(0.0f, frame);
  const double a90 = ros_angle_rad(90.0f, frame);
  const double z = std::sin(a90 - a0);  // +1 or -1: -1 when the unit sweeps clockwise about +z
  const double m[3][3] = {{std::cos(a0), std::cos(a90), 0}, {std::sin(a0), std::sin(a90), 0}, {0, 0, z}};
  RosTransform t;
  t.parent_frame = laser_frame;
  t.child_frame = unit_frame_id(laser_frame);
  // The rotation matrix as a quaternion (Shepperd: from the largest of w, x, y, z, for precision).
  const double trace = m[0][0] + m[1][1] + m[2][2];
  double* q = t.rotation;  // x, y, z, w
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    q[3] = s / 4;
    q[0] = (m[2][1] - m[1][2]) / s;
    q[1] = (m[0][2] - m[2][0]) / s;
    q[2] = (m[1][0] - m[0][1]) / s;
  } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
    const double s = 2 * std::sqrt(1 + m[0][0] - m[1][1] - m[2][2]);
    q[0] = s / 4;
    q[3] = (m[2][1] - m[1][2]) / s;
    q[1] = (m[0][1] + m[1][0]) / s;
    q[2] = (m[0][2] + m[2][0]) / s;
  } else if (m[1][1] >= m[2][2]) {
    const double s = 2 * std::sqrt(1 + m[1][1] - m[0][0] - m[2][2]);
    q[1] = s / 4;
    q[3] = (m[0][2] - m[2][0]) / s;
    q[0] = (m[0][1] + m[1][0]) / s;
    q[2] = (m[1][2] + m[2][1]) / s;
  } else {
    const double s = 2 * std::sqrt(1 + m[2][2] - m[0][0] - m[1][1]);
    q[2] = s / 4;
    q[3] = (m[1][0] - m[0][1]) / s;
    q[0] = (m[0][2] + m[2][0]) / s;
    q[1] = (m[1][2] + m[2][1]) / s;
  }
  return t;
}

void append_lidar_transforms(const Pose& pose, const RosFrameOptions& frame, const std::string& parent,
                             const std::string& laser_frame, std::vector<RosTransform>& out) {
  out.push_back(ros_transform_of(pose, frame, parent, laser_frame));
  out.push_back(ros_unit_transform(frame, laser_frame));
}

void encode_tf_message(std::span<const RosTransform> transforms, std::uint64_t stamp_ns,
                       std::vector<std::uint8_t>& out) {
  CdrWriter cdr(out);
  cdr.u32(static_cast<std::uint32_t>(transforms.size()));
  for (const RosTransform& t : transforms) {
    cdr.i32(static_cast<std::int32_t>(stamp_ns / 1'000'000'000u));
    cdr.u32(static_cast<std::uint32_t>(stamp_ns % 1'000'000'000u));
    cdr.string(t.parent_frame);
    cdr.string(t.child_frame);
    for (const double v : t.translation) cdr.f64(v);
    for (const double v : t.rotation) cdr.f64(v);
  }
}

}  // namespace ydscope
