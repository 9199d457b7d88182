// CosinePower (Sampling.hpp) for whole exponents, in SIMD lanes for every Highway target:
// included by each kernel file's foreach_target pass (Highway's -inl.h convention: the
// guard toggles per target). The scalar loop's products in its order, so every lane
// gives its bits; -ffp-contract=off keeps them apart.
// NOLINTBEGIN(llvm-header-guard)
#if defined(GLINT_COSINE_POWER_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLINT_COSINE_POWER_LANES_INL_H_
#undef GLINT_COSINE_POWER_LANES_INL_H_
#else
#define GLINT_COSINE_POWER_LANES_INL_H_
#endif
// NOLINTEND(llvm-header-guard)

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {

// c^n for a whole n of at most `bits` bits, by squaring: power *= base where bit b of n
// is set, base *= base. (Past n's top bit the power no longer changes.)
template <class D>
hwy::HWY_NAMESPACE::Vec<D> CosinePowerLanes(D d, hwy::HWY_NAMESPACE::Vec<D> c,
                                            hwy::HWY_NAMESPACE::Vec<D> n, int bits) {
  namespace hn = hwy::HWY_NAMESPACE;
  using V = hn::Vec<D>;
  const V half = hn::Set(d, 0.5);
  V power = hn::Set(d, 1.0);
  V base = c;
  V k = n;
  for (int b = 0; b < bits; ++b) {
    const V next = hn::Floor(hn::Mul(k, half));
    power = hn::IfThenElse(hn::Ne(k, hn::Add(next, next)), hn::Mul(power, base), power);
    base = hn::Mul(base, base);
    k = next;
  }
  return power;
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#endif  // GLINT_COSINE_POWER_LANES_INL_H_
