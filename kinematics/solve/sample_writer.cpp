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

} // namespace

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
}

void SampleWriter::write(std::size_t j, const Pose& pose) {
  for (const PointSlot& s : m_points) {
    s.position[j] = pose.position[s.point];
    if (s.velocity != nullptr) s.velocity[j] = pose.velocity[s.point];
    if (s.acceleration != nullptr) s.acceleration[j] = pose.acceleration[s.point];
    if (s.transmission != nullptr) s.transmission[j] = pose.transmissionAngle[s.point];
  }
  for (const LinkSlot& s : m_links) {
    const double raw = pose.linkAngle[s.link];
    const double last = s.angle[m_lastWritten];
    s.angle[j] = m_haveAngle ? last + wrapAngle(raw - last) : raw;
    if (s.omega != nullptr) s.omega[j] = pose.linkOmega[s.link];
    if (s.alpha != nullptr) s.alpha[j] = pose.linkAlpha[s.link];
  }
  m_lastWritten = j;
  m_haveAngle = true;
}

// Every sample gets the pivot's position, then the few that did not assemble get zero.
void SampleWriter::finish(const Mechanism& m, SweepResult& out) const {
  const std::size_t n = out.size();
  for (const PointSlot& s : m_ground) {
    std::fill_n(s.position, n, std::get<GroundPoint>(m.points[s.point].definition).position);
    for (std::size_t j = 0; j < n; ++j)
      if (!out.assembled(j)) s.position[j].setZero();
    if (s.velocity != nullptr) std::fill_n(s.velocity, n, Eigen::Vector2d::Zero());
    if (s.acceleration != nullptr) std::fill_n(s.acceleration, n, Eigen::Vector2d::Zero());
  }
}

void SampleWriter::writeNothing(std::size_t j) {
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

} // namespace linkwright::kinematics
