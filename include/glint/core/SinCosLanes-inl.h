// SinCosTurns (SinCos.hpp) in SIMD lanes for every Highway target: included by each
// kernel file's foreach_target pass (Highway's -inl.h convention: the guard toggles per
// target). Each line is the scalar function's operation in its order, so every lane
// gives its bits; -ffp-contract=off keeps products and sums apart.
// NOLINTBEGIN(llvm-header-guard)
#if defined(GLINT_SIN_COS_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLINT_SIN_COS_LANES_INL_H_
#undef GLINT_SIN_COS_LANES_INL_H_
#else
#define GLINT_SIN_COS_LANES_INL_H_
#endif
// NOLINTEND(llvm-header-guard)

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {

template <class V>
struct SinCosLanes {
  V sin;
  V cos;
};

// sin(2 pi u) and cos(2 pi u), lane by lane: SinCosTurns' quarter turns and Estrin
// polynomials.
template <class D>
SinCosLanes<hwy::HWY_NAMESPACE::Vec<D>> SinCosTurnsLanes(D d, hwy::HWY_NAMESPACE::Vec<D> u) {
  namespace hn = hwy::HWY_NAMESPACE;
  using V = hn::Vec<D>;
  const auto set = [d](double x) { return hn::Set(d, x); };
  const V round = set(0x1.8p52);
  const V e = hn::Mul(set(4.0), u);
  const V q = hn::Sub(hn::Add(e, round), round);
  const V f = hn::Sub(e, q);
  const V x = hn::Mul(f, set(1.57079632679489661923));
  const V x2 = hn::Mul(x, x);
  const V x4 = hn::Mul(x2, x2);
  const V x8 = hn::Mul(x4, x4);
  const auto pair = [&](double a, double b) { return hn::Add(set(a), hn::Mul(x2, set(b))); };
  const V sPoly = hn::Add(
      hn::Add(pair(-1.0 / 6.0, 1.0 / 120.0), hn::Mul(x4, pair(-1.0 / 5040.0, 1.0 / 362880.0))),
      hn::Mul(x8, hn::Add(pair(-1.0 / 39916800.0, 1.0 / 6227020800.0),
                          hn::Mul(x4, pair(-1.0 / 1307674368000.0, 1.0 / 355687428096000.0)))));
  const V s = hn::Add(x, hn::Mul(hn::Mul(x, x2), sPoly));
  const V cPoly = hn::Add(
      hn::Add(pair(-1.0 / 2.0, 1.0 / 24.0), hn::Mul(x4, pair(-1.0 / 720.0, 1.0 / 40320.0))),
      hn::Mul(x8, hn::Add(pair(-1.0 / 3628800.0, 1.0 / 479001600.0),
                          hn::Mul(x4, pair(-1.0 / 87178291200.0, 1.0 / 20922789888000.0)))));
  const V c = hn::Add(set(1.0), hn::Mul(x2, cPoly));
  // The quarter turn q mod 4, from q's whole value.
  const hn::RebindToSigned<D> di;
  const auto quarter = hn::ConvertTo(di, q);
  const auto bit = [&](decltype(quarter) k, long long b) {
    return hn::RebindMask(d, hn::Ne(hn::And(k, hn::Set(di, b)), hn::Zero(di)));
  };
  const auto odd = bit(quarter, 1);
  const V sine = hn::IfThenElse(odd, c, s);
  const V cosine = hn::IfThenElse(odd, s, c);
  const auto next = hn::Add(quarter, hn::Set(di, 1));
  return {hn::IfThenElse(bit(quarter, 2), hn::Neg(sine), sine),
          hn::IfThenElse(bit(next, 2), hn::Neg(cosine), cosine)};
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#endif  // GLINT_SIN_COS_LANES_INL_H_
