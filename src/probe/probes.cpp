// probes.cpp - the probe table (probes.h).
#include "probe/probes.h"

namespace cdmpm {

template <int dim>
Probes<dim>::Probes(const Scene& scene, const Simulation<dim>& sim) : probes_(make_probes<dim>(scene)) {
  for (auto& p : probes_) p->init(sim);
}

template <int dim>
std::string Probes<dim>::csv_header() const {
  std::string h = "time";
  for (const auto& p : probes_)
    for (const std::string& c : p->columns()) h += "," + c;
  return h;
}

template <int dim>
std::vector<Station> Probes<dim>::stations() const {
  std::vector<Station> out;
  for (const auto& p : probes_)
    for (Station& s : p->stations()) out.push_back(std::move(s));
  return out;
}

template <int dim>
std::vector<double> Probes<dim>::sample(const Simulation<dim>& sim) const {
  std::vector<double> out;
  for (const auto& p : probes_) p->sample(sim, out);
  return out;
}

template <int dim>
std::vector<double> Probes<dim>::save_state() const {
  std::vector<double> out;
  for (const auto& p : probes_) {
    const std::vector<double> s = p->save_state();
    out.push_back(static_cast<double>(s.size()));
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

template <int dim>
bool Probes<dim>::load_state(const std::vector<double>& state) {
  size_t k = 0;
  for (auto& p : probes_) {
    if (k >= state.size() || !(state[k] >= 0) || state[k] > double(state.size() - k - 1)) return false;
    const size_t n = static_cast<size_t>(state[k++]);
    if (!p->load_state(std::vector<double>(state.begin() + k, state.begin() + k + n))) return false;
    k += n;
  }
  return k == state.size();
}

template class Probes<2>;
template class Probes<3>;

}  // namespace cdmpm
