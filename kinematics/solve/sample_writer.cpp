#include "kinematics/solve/sample_writer.h"

#include "kinematics/model/units.h"

#include <algorithm>

namespace linkwright::kinematics {
namespace {

// The column's storage, or null where the quantity or the entry was not requested.
template <typename T>
T* columnData(std::vector<std::vector<T>>& columns, std::size_t i) {
  if (i >= columns.size() || columns[i].empty()) return nullptr;
  return columns[i].data();
}

// Copies field[i] of each pose into column[j], column[j + 1], … The column and the index are
// held in locals: a store through the column may alias the writer's slots as far as the
// compiler knows, so it would reload them for every sample.
template <typename T>
void copyColumn(T* column, std::size_t j, std::span<const Pose> poses, std::vector<T> Pose::*field, std::size_t i) {
  if (column == nullptr) return;
  for (std::size_t b = 0; b < poses.size(); ++b) column[j + b] = (poses[b].*field)[i];
}

}  // namespace

SampleWriter::SampleWriter(const Mechanism& m, SweepResult& out) {
  for (std::size_t i = 0; i < out.position.size(); ++i) {
    if (out.position[i].empty()) continue;
    const PointSlot slot{i, out.position[i].data(), columnData(out.velocity, i), columnData(out.acceleration, i),
                         columnData(out.transmissionAngle, i)};
    (std::holds_alternative<GroundPoint>(m.points[i].definition) ? m_ground : m_points).push_back(slot);
  }
  for (std::size_t k = 0; k < out.linkAngle.size(); ++k) {
    if (out.linkAngle[k].empty()) continue;
    m_links.push_back({k, out.linkAngle[k].data(), columnData(out.linkOmega, k), columnData(out.linkAlpha, k)});
  }
  m_lastAngle.assign(m_links.size(), 0.0);
}

void SampleWriter::write(std::size_t j, std::span<const Pose> poses) {
  if (poses.empty()) return;
  for (const PointSlot& s : m_points) {
    copyColumn(s.position, j, poses, &Pose::position, s.point);
    copyColumn(s.velocity, j, poses, &Pose::velocity, s.point);
    copyColumn(s.acceleration, j, poses, &Pose::acceleration, s.point);
    copyColumn(s.transmission, j, poses, &Pose::transmissionAngle, s.point);
  }
  for (std::size_t l = 0; l < m_links.size(); ++l) {
    const LinkSlot& s = m_links[l];
    double* const angle = s.angle;
    const std::size_t k = s.link;
    const double previous = m_lastAngle[l];
    double last = m_haveAngle ? previous + wrapAngle(poses[0].linkAngle[k] - previous) : poses[0].linkAngle[k];
    angle[j] = last;
    for (std::size_t b = 1; b < poses.size(); ++b) {
      last += wrapAngle(poses[b].linkAngle[k] - last);
      angle[j + b] = last;
    }
    m_lastAngle[l] = last;
    copyColumn(s.omega, j, poses, &Pose::linkOmega, k);
    copyColumn(s.alpha, j, poses, &Pose::linkAlpha, k);
  }
  m_haveAngle = true;
}

// Every sample gets the pivot's position, then the few that did not assemble get zero.
void SampleWriter::finish(const Mechanism& m, SweepResult& out) {
  const std::size_t n = out.size();
  for (const PointSlot& s : m_ground) {
    std::fill_n(s.position, n, std::get<GroundPoint>(m.points[s.point].definition).position);
    if (m_wroteNothing)
      for (std::size_t j = 0; j < n; ++j)
        if (!out.assembled(j)) s.position[j].setZero();
    if (s.velocity != nullptr) std::fill_n(s.velocity, n, Eigen::Vector2d::Zero());
    if (s.acceleration != nullptr) std::fill_n(s.acceleration, n, Eigen::Vector2d::Zero());
  }
  m_wroteNothing = false;  // the next window, if any, starts afresh
}

void SampleWriter::writeNothing(std::size_t j) {
  m_wroteNothing = true;
  for (const PointSlot& s : m_points) {
    s.position[j].setZero();
    if (s.velocity != nullptr) s.velocity[j].setZero();
    if (s.acceleration != nullptr) s.acceleration[j].setZero();
    if (s.transmission != nullptr) s.transmission[j] = 0.0;
  }
  for (const LinkSlot& s : m_links) {
    s.angle[j] = 0.0;
    if (s.omega != nullptr) s.omega[j] = 0.0;
    if (s.alpha != nullptr) s.alpha[j] = 0.0;
  }
}

void clearRates(Pose& pose) {
  std::fill(pose.velocity.begin(), pose.velocity.end(), Eigen::Vector2d::Zero());
  std::fill(pose.acceleration.begin(), pose.acceleration.end(), Eigen::Vector2d::Zero());
  std::fill(pose.linkOmega.begin(), pose.linkOmega.end(), 0.0);
  std::fill(pose.linkAlpha.begin(), pose.linkAlpha.end(), 0.0);
}

}  // namespace linkwright::kinematics
