#include "core/export/ros_tf.h"

#include <cmath>
#include <numbers>

#include "core/export/cdr_writer.h"

namespace ydscope {
namespace {

using Matrix = double[2][2];

// The view frame (x right, y forward; Pose's) into the ROS laser frame of `frame`: its columns
// are where device angles 90 (view x) and 0 (view y) land.
void view_to_ros(const RosFrameOptions& frame, Matrix& q) {
  const double a90 = ros_angle_rad(90.0f, frame);
  const double a0 = ros_angle_rad(0.0f, frame);
  q[0][0] = std::cos(a90);
  q[1][0] = std::sin(a90);
  q[0][1] = std::cos(a0);
  q[1][1] = std::sin(a0);
}

void multiply(const Matrix& a, const Matrix& b, Matrix& out) {
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) out[r][c] = a[r][0] * b[0][c] + a[r][1] * b[1][c];
}

}  // namespace

RosTransform ros_transform_of(const Pose& pose, const RosFrameOptions& frame, std::string parent, std::string child) {
  Matrix q;
  view_to_ros(frame, q);
  // q is orthogonal, so its inverse is its transpose.
  const Matrix q_inverse = {{q[0][0], q[1][0]}, {q[0][1], q[1][1]}};
  const double yaw = pose.yaw_deg * std::numbers::pi / 180.0;
  const Matrix turn = {{std::cos(yaw), -std::sin(yaw)}, {std::sin(yaw), std::cos(yaw)}};
  const Matrix mirror = {{pose.upside_down ? -1.0 : 1.0, 0}, {0, 1}};
  // In the view: common = turn * mirror * laser + shift. In ROS axes: q * that * q^-1.
  Matrix a, b, linear;
  multiply(turn, mirror, a);
  multiply(q, a, b);
  multiply(b, q_inverse, linear);

  RosTransform t;
  t.parent_frame = std::move(parent);
  t.child_frame = std::move(child);
  t.translation[0] = q[0][0] * pose.x_m + q[0][1] * pose.y_m;
  t.translation[1] = q[1][0] * pose.x_m + q[1][1] * pose.y_m;
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
