#include "core/patch/transfinite/blends.hpp"

#include "core/patch/transfinite/ribbon_set.hpp"

namespace pl::transfinite {

namespace {

// out[i] = product of f[j] over j outside the cyclic run i, i+1, ..., i+skip-1 (skip = 1 or 2),
// by prefix and suffix products (O(n)).
std::vector<Jet> products_without(const std::vector<Jet>& f, int skip) {
  const int n = static_cast<int>(f.size());
  std::vector<Jet> prefix(n + 1, Jet(1.0)), suffix(n + 1, Jet(1.0));
  for (int j = 0; j < n; ++j) prefix[j + 1] = prefix[j] * f[j];
  for (int j = n - 1; j >= 0; --j) suffix[j] = f[j] * suffix[j + 1];
  std::vector<Jet> out(n);
  for (int i = 0; i < n; ++i) {
    const int last = i + skip - 1;
    if (last < n) {
      out[i] = prefix[i] * suffix[last + 1];
    } else {  // the run wraps: j from (last - n) + 1 to i - 1
      Jet p(1.0);
      for (int j = last - n + 1; j < i; ++j) p = p * f[j];
      out[i] = p;
    }
  }
  return out;
}

std::vector<Jet> normalized(std::vector<Jet> w) {
  Jet sum(0.0);
  for (const Jet& x : w) sum += x;
  const Jet r = reciprocal(sum);
  for (Jet& x : w) x = x * r;
  return w;
}

std::vector<Jet> squares(const std::vector<Jet>& d) {
  std::vector<Jet> sq;
  sq.reserve(d.size());
  for (const Jet& x : d) sq.push_back(x * x);
  return sq;
}

}  // namespace

std::vector<Jet> side_blend(const std::vector<Jet>& d) {
  return normalized(products_without(squares(d), 1));
}

std::vector<Jet> corner_blend(const std::vector<Jet>& d) {
  return normalized(products_without(squares(d), 2));
}

std::vector<Jet> deficient_corner_blend(const std::vector<Jet>& s, const std::vector<Jet>& d) {
  const int n = static_cast<int>(d.size());
  std::vector<Jet> w(n);
  for (int i = 0; i < n; ++i) {
    const int k = (i + 1) % n;
    if (d[i].f < 1e-8 && d[k].f < 1e-8) {
      w[i] = Jet(1.0);
      continue;
    }
    w[i] = (d[k] * hermite_blend(1.0 - s[i]) * hermite_blend(d[i]) +
            d[i] * hermite_blend(s[k]) * hermite_blend(d[k])) /
           (d[i] + d[k]);
  }
  return w;
}

}  // namespace pl::transfinite
