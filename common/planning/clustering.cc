#include "common/planning/clustering.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace hexplore::planning {
namespace {

void finish(TaskCluster& c, const std::vector<TaskView>& views) {
  std::sort(c.views.begin(), c.views.end(), [&](int a, int b) { return views[size_t(a)].key < views[size_t(b)].key; });
  c.id = views[size_t(c.views.front())].key;
  c.center.setZero();
  c.facade_views = 0;
  for (int v : c.views) {
    c.center += views[size_t(v)].position;
    c.facade_views += views[size_t(v)].facade ? 1 : 0;
  }
  c.center /= double(c.views.size());
}

}  // namespace

std::vector<TaskCluster> cluster_views(const std::vector<TaskView>& views, double eta_r_m) {
  // Per label, the view indices in key order (ties, which a well-formed map never has, by position).
  std::map<int, std::vector<int>> by_label;
  std::vector<int> order(views.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto& va = views[size_t(a)];
    const auto& vb = views[size_t(b)];
    if (va.key != vb.key) return va.key < vb.key;
    return std::lexicographical_compare(va.position.data(), va.position.data() + 3, vb.position.data(), vb.position.data() + 3);
  });
  for (int i : order) by_label[views[size_t(i)].label].push_back(i);

  const double r2 = eta_r_m * eta_r_m;
  std::vector<TaskCluster> clusters;
  for (auto& [label, list] : by_label) {
    std::vector<char> taken(list.size(), 0);
    for (size_t first = 0; first < list.size(); ++first) {
      if (taken[first]) continue;
      TaskCluster c;
      c.label = label;
      c.views.push_back(list[first]);
      taken[first] = 1;
      Eigen::Vector3d sum = views[size_t(list[first])].position;
      bool grew = true;
      while (grew) {
        grew = false;
        for (size_t j = first + 1; j < list.size(); ++j) {
          if (taken[j]) continue;
          const Eigen::Vector3d center = sum / double(c.views.size());
          if ((views[size_t(list[j])].position - center).squaredNorm() > r2) continue;
          taken[j] = 1;
          c.views.push_back(list[j]);
          sum += views[size_t(list[j])].position;
          grew = true;
        }
      }
      finish(c, views);
      clusters.push_back(std::move(c));
    }
  }
  std::sort(clusters.begin(), clusters.end(), [](const TaskCluster& a, const TaskCluster& b) { return a.id < b.id; });
  return clusters;
}

std::vector<TaskCluster> singleton_clusters(const std::vector<TaskView>& views) {
  std::vector<TaskCluster> clusters;
  clusters.reserve(views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    TaskCluster c;
    c.label = views[i].label;
    c.views = {int(i)};
    finish(c, views);
    clusters.push_back(std::move(c));
  }
  std::sort(clusters.begin(), clusters.end(), [](const TaskCluster& a, const TaskCluster& b) { return a.id < b.id; });
  return clusters;
}

}  // namespace hexplore::planning
