//! Knot vectors: the textbook's uniform and open uniform constructors (`gllUniknots`,
//! `gllOpenUniknots`, seed 004 §9.6.2), span search (The NURBS Book A2.1 FindSpan), breakpoints,
//! and GLU's knot-vector validation (`knotvector.cc` `Knotvector::validate`, error numbers 1..=5).
//!
//! Convention (the textbook's and GL's): **order** = degree + 1, and a spline with `npts` control
//! points has `npts + order` knots. The curve is defined on the *valid range*
//! [knots\[order−1\], knots\[npts\]] (seed 004 §9.5.2: [u_{d−1}, u_{n+1}]).

use super::scalar::Scalar;
use super::MathError;

/// GLU's largest spline order (`internals/defines.h` `MAXORDER`), smaller than GL's 30.
pub const GLU_MAX_ORDER: usize = 24;

/// GLU's knot coincidence tolerance (`knotvector.h` `TOLERANCE`): knots closer than this are
/// treated as one breakpoint. Checked against real GLU 9.0: 5e−6 apart coincide, 5e−5 do not.
pub const GLU_TOLERANCE: f64 = 1e-5;

/// Why GLU rejects a knot vector; [`GluKnotError::number`] is GLU's error number
/// (`GLU_NURBS_ERRORn`), [`GluKnotError::message`] its `gluErrorString` text, typos included.
///
/// ```
/// use gleval::math::{GluKnotError, KnotVector};
/// let kv = KnotVector::new(vec![0.0f32, 0.0, 1.0, 0.5, 1.0, 1.0]);
/// assert_eq!(kv.glu_check(2), Err(GluKnotError::Decreasing));
/// assert_eq!(GluKnotError::Decreasing.number(), 4);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GluKnotError {
    /// 1: order < 1 or order > 24.
    OrderUnsupported,
    /// 2: fewer than 2·order knots.
    TooFewKnots,
    /// 3: knot\[nknots−order\] − knot\[order−1\] < 1e−5 (signed).
    EmptyRange,
    /// 4: some knot\[i\] > knot\[i+1\].
    Decreasing,
    /// 5: a run of knots closer than 1e−5 is longer than the order.
    MultiplicityTooHigh,
}

impl GluKnotError {
    /// GLU's error number, 1..=5 (`GLU_NURBS_ERROR1 + number − 1` is the callback's code).
    #[must_use]
    pub fn number(self) -> u32 {
        match self {
            Self::OrderUnsupported => 1,
            Self::TooFewKnots => 2,
            Self::EmptyRange => 3,
            Self::Decreasing => 4,
            Self::MultiplicityTooHigh => 5,
        }
    }

    /// GLU's message for this error (`glue.c` `__gluNurbsErrors`), verbatim.
    #[must_use]
    pub fn message(self) -> &'static str {
        match self {
            Self::OrderUnsupported => "spline order un-supported",
            Self::TooFewKnots => "too few knots",
            Self::EmptyRange => "valid knot range is empty",
            Self::Decreasing => "decreasing knot sequence knot",
            Self::MultiplicityTooHigh => "knot multiplicity greater than order of spline",
        }
    }
}

impl core::fmt::Display for GluKnotError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.message())
    }
}

impl std::error::Error for GluKnotError {}

impl From<GluKnotError> for MathError {
    fn from(e: GluKnotError) -> Self {
        MathError::Knots(e.message())
    }
}

/// Builds `len` knots with `f`, or `None` if `len` cannot be allocated (never aborts).
fn build<S: Scalar>(len: Option<usize>, f: impl FnOnce(&mut Vec<S>)) -> Option<Vec<S>> {
    let mut knots = Vec::new();
    knots.try_reserve_exact(len?).ok()?;
    f(&mut knots);
    Some(knots)
}

/// The span index of A2.1 for sorted `knots`: the `i` in `order−1 ..= npts−1` with
/// knots\[i\] ≤ u < knots\[i+1\], the right end u = knots\[npts\] going to the last non-empty span.
///
/// `None` if `order` is 0, there are fewer than `2·order` knots, the valid range is empty, or `u`
/// is outside it or NaN. Unsorted knots give some index in range, never a panic or a hang: the
/// search is a bisection (`partition_point`) rather than A2.1's open loop.
#[must_use]
pub fn find_span<S: Scalar>(knots: &[S], order: usize, u: S) -> Option<usize> {
    let p = order.checked_sub(1)?;
    let n = knots.len().checked_sub(order)?;
    if n < order {
        return None;
    }
    let (lo, hi) = (knots[p], knots[n]);
    if !(lo < hi && u >= lo && u <= hi) {
        return None;
    }
    let inner = &knots[p + 1..n];
    let count = if u < hi { inner.partition_point(|&k| k <= u) } else { inner.partition_point(|&k| k < hi) };
    Some(p + count)
}

/// A knot vector: non-decreasing parameter values, `npts + order` of them for a spline of
/// `npts` control points.
///
/// ```
/// use gleval::math::KnotVector;
/// // Seed 004 §9.5.3: 6 points, order 4 (cubic) open uniform.
/// let kv = KnotVector::<f32>::open_uniform(6, 4).unwrap();
/// assert_eq!(kv.knots, [0., 0., 0., 0., 1., 2., 3., 3., 3., 3.]);
/// assert_eq!(kv.valid_range(4), Some((0.0, 3.0)));
/// assert_eq!(kv.find_span(4, 1.5), Some(4));
/// assert_eq!(kv.breakpoints(4), [0.0, 1.0, 2.0, 3.0]);
/// assert!(kv.glu_check(4).is_ok());
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct KnotVector<S: Scalar> {
    /// The knot values.
    pub knots: Vec<S>,
}

impl<S: Scalar> KnotVector<S> {
    /// Wraps knot values as given (no check; see [`KnotVector::glu_check`]).
    #[must_use]
    pub fn new(knots: Vec<S>) -> Self {
        Self { knots }
    }

    /// The textbook's `gllUniknots`: knots\[i\] = i for i in 0..npts+order.
    /// `None` only if the count overflows or cannot be allocated.
    ///
    /// ```
    /// use gleval::math::KnotVector;
    /// assert_eq!(KnotVector::<f64>::uniform(3, 3).unwrap().knots, [0., 1., 2., 3., 4., 5.]);
    /// ```
    #[must_use]
    pub fn uniform(npts: usize, order: usize) -> Option<Self> {
        let len = npts.checked_add(order);
        let knots = build(len, |k| k.extend((0..npts + order).map(S::from_usize)))?;
        Some(Self { knots })
    }

    /// The textbook's `gllOpenUniknots`: `order` zeros, then i − order + 1 for i in order..npts,
    /// then npts − order + 1 up to npts + order knots. Reproduces the C loops exactly, even when
    /// npts < order (the last loop then overwrites some zeros, with a value that may be negative).
    ///
    /// ```
    /// use gleval::math::KnotVector;
    /// // Seed 004 §9.5.3: d = 2, n = 4.
    /// assert_eq!(KnotVector::<f64>::open_uniform(5, 2).unwrap().knots, [0., 0., 1., 2., 3., 4., 4.]);
    /// ```
    #[must_use]
    pub fn open_uniform(npts: usize, order: usize) -> Option<Self> {
        let len = npts.checked_add(order)?;
        let last = S::from_f64(npts as f64 - order as f64 + 1.0);
        let knots = build(Some(len), |k| {
            k.resize(len, S::ZERO);
            for (i, knot) in k.iter_mut().enumerate().take(npts).skip(order) {
                *knot = S::from_usize(i + 1 - order);
            }
            k[npts..].fill(last);
        })?;
        Some(Self { knots })
    }

    /// Number of knots.
    #[must_use]
    pub fn len(&self) -> usize {
        self.knots.len()
    }

    /// No knots at all.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.knots.is_empty()
    }

    /// Control points a spline of this `order` has: knots − order (`None` if negative).
    #[must_use]
    pub fn control_count(&self, order: usize) -> Option<usize> {
        self.knots.len().checked_sub(order)
    }

    /// The valid parameter range [knots\[order−1\], knots\[npts\]], `None` if there are fewer than
    /// `2·order` knots or `order` is 0. The range may be empty or reversed for bad knots.
    #[must_use]
    pub fn valid_range(&self, order: usize) -> Option<(S, S)> {
        let n = self.control_count(order)?;
        if order == 0 || n < order {
            return None;
        }
        Some((self.knots[order - 1], self.knots[n]))
    }

    /// The span of `u` (The NURBS Book A2.1 FindSpan); see [`find_span`].
    #[must_use]
    pub fn find_span(&self, order: usize, u: S) -> Option<usize> {
        find_span(&self.knots, order, u)
    }

    /// How many knots equal `u` exactly (the `s` of The NURBS Book A5.1).
    #[must_use]
    pub fn multiplicity(&self, u: S) -> usize {
        self.knots.iter().filter(|&&k| k == u).count()
    }

    /// The distinct breakpoints within the valid range, both ends included, ascending.
    /// A knot less than 1e−5 above the last kept breakpoint is the same breakpoint (GLU's
    /// `identical`). Empty if the valid range is missing or empty.
    #[must_use]
    pub fn breakpoints(&self, order: usize) -> Vec<S> {
        let Some((lo, hi)) = self.valid_range(order) else {
            return Vec::new();
        };
        if lo.partial_cmp(&hi) != Some(core::cmp::Ordering::Less) {
            return Vec::new();
        }
        let tol = S::from_f64(GLU_TOLERANCE);
        let mut out = vec![lo];
        for &k in &self.knots[order - 1..self.knots.len() - order] {
            if k - out[out.len() - 1] >= tol && k < hi {
                out.push(k);
            }
        }
        if hi - out[out.len() - 1] >= tol {
            out.push(hi);
        }
        out
    }

    /// GLU's `Knotvector::validate`, checks in GLU's order: 1 order outside 1..=24, 2 fewer than
    /// 2·order knots, 3 empty valid range (signed, tolerance 1e−5), 4 a decreasing pair, 5 a run of
    /// knots each closer than 1e−5 to the next that is longer than `order`.
    ///
    /// GLU computes in `f32`; with `S = f64` differences within rounding of 1e−5 may decide the
    /// other way. NaN knots pass, as in GLU.
    pub fn glu_check(&self, order: usize) -> Result<(), GluKnotError> {
        if !(1..=GLU_MAX_ORDER).contains(&order) {
            return Err(GluKnotError::OrderUnsupported);
        }
        self.check_knots(order)
    }

    /// GLU's checks 2..=5 alone (see [`KnotVector::glu_check`]), for orders GLU would refuse
    /// but GL accepts (up to 30). Order 0 is reported as [`GluKnotError::OrderUnsupported`].
    pub fn check_knots(&self, order: usize) -> Result<(), GluKnotError> {
        let k = &self.knots;
        let tol = S::from_f64(GLU_TOLERANCE);
        if order == 0 {
            return Err(GluKnotError::OrderUnsupported);
        }
        if k.len() < order.saturating_mul(2) {
            return Err(GluKnotError::TooFewKnots);
        }
        if k[k.len() - order] - k[order - 1] < tol {
            return Err(GluKnotError::EmptyRange);
        }
        if k.windows(2).any(|w| w[0] > w[1]) {
            return Err(GluKnotError::Decreasing);
        }
        if longest_run(k, tol) > order {
            return Err(GluKnotError::MultiplicityTooHigh);
        }
        Ok(())
    }
}

/// The longest run of knots each within `tol` of the next (GLU's multiplicity loop).
fn longest_run<S: Scalar>(knots: &[S], tol: S) -> usize {
    let (mut run, mut longest) = (1, 1);
    for w in knots.windows(2) {
        run = if w[1] - w[0] < tol { run + 1 } else { 1 };
        longest = longest.max(run);
    }
    longest
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn textbook_open_uniform_examples() {
        // Seed 004 §9.5.3: n = 5, d = 4 and n = 4, d = 2, written out in the text.
        let a = KnotVector::<f64>::open_uniform(6, 4).unwrap();
        assert_eq!(a.knots, [0., 0., 0., 0., 1., 2., 3., 3., 3., 3.]);
        let b = KnotVector::<f32>::open_uniform(5, 2).unwrap();
        assert_eq!(b.knots, [0., 0., 1., 2., 3., 4., 4.]);
    }

    #[test]
    fn textbook_uniform_examples() {
        // §9.5.3 (3): 5 points, order 3 -> {0..7}; §9.5.4: 3 points, order 3 -> {0..5}.
        let a = KnotVector::<f64>::uniform(5, 3).unwrap();
        assert_eq!(a.knots, [0., 1., 2., 3., 4., 5., 6., 7.]);
        assert_eq!(KnotVector::<f64>::uniform(3, 3).unwrap().valid_range(3), Some((2.0, 3.0)));
        // §9.5.2 note: 4 points, cubic, {0..7} -> curve defined on [3, 4].
        assert_eq!(a.valid_range(4), Some((3.0, 4.0)));
    }

    #[test]
    fn open_uniform_with_too_few_points_follows_the_c_loops() {
        // npts = 2, order = 4: zeros at 0..4, then knots[2..6] = 2 - 4 + 1 = -1.
        let kv = KnotVector::<f64>::open_uniform(2, 4).unwrap();
        assert_eq!(kv.knots, [0., 0., -1., -1., -1., -1.]);
        assert!(KnotVector::<f64>::uniform(usize::MAX, 2).is_none());
    }

    #[test]
    fn find_span_matches_definition_and_clamps_right_end() {
        let kv = KnotVector::new(vec![0.0f64, 0., 0., 1., 2., 2., 3., 3., 3.]);
        // order 3, 6 points: valid range [0, 3]; spans 2 ([0,1)), 3 ([1,2)), 5 ([2,3)).
        assert_eq!(kv.find_span(3, 0.0), Some(2));
        assert_eq!(kv.find_span(3, 1.0), Some(3));
        assert_eq!(kv.find_span(3, 1.99), Some(3));
        assert_eq!(kv.find_span(3, 2.0), Some(5));
        assert_eq!(kv.find_span(3, 3.0), Some(5));
        assert_eq!(kv.find_span(3, 3.5), None);
        assert_eq!(kv.find_span(3, -0.1), None);
        assert_eq!(kv.find_span(3, f64::NAN), None);
        assert_eq!(kv.find_span(0, 1.0), None);
        assert_eq!(kv.find_span(5, 1.0), None);
    }

    #[test]
    fn multiplicity_and_breakpoints_with_tolerance() {
        let kv = KnotVector::new(vec![0.0f64, 0., 0., 1., 1. + 4e-6, 2., 3., 3., 3.]);
        assert_eq!(kv.multiplicity(0.0), 3);
        assert_eq!(kv.multiplicity(1.0), 1);
        assert_eq!(kv.breakpoints(3), [0.0, 1.0, 2.0, 3.0]);
        // Uniform cubic, 4 points: only [3, 4] is valid.
        assert_eq!(KnotVector::<f32>::uniform(4, 4).unwrap().breakpoints(4), [3.0, 4.0]);
        assert!(KnotVector::new(vec![1.0f64, 1.0, 1.0, 1.0]).breakpoints(2).is_empty());
    }

    fn check(knots: &[f32], order: usize) -> u32 {
        KnotVector::new(knots.to_vec()).glu_check(order).map_or_else(|e| e.number(), |()| 0)
    }

    #[test]
    fn each_glu_error_is_provoked() {
        // Numbers and tolerances confirmed against libGLU 9.0 with an OSMesa program.
        assert_eq!(check(&[0., 0., 1., 1.], 2), 0);
        assert_eq!(check(&[0., 0., 1., 1.], 25), 1);
        assert_eq!(check(&[0., 0., 1., 1.], 0), 1);
        assert_eq!(check(&[0., 0., 1.], 2), 2);
        assert_eq!(check(&[0., 0., 4e-6, 4e-6], 2), 3);
        assert_eq!(check(&[1., 1., 0., 0.], 2), 3); // signed: a reversed range is empty
        assert_eq!(check(&[0., 0., 5e-5, 5e-5], 2), 0);
        assert_eq!(check(&[0., 0., 1., 0.5, 1., 1.], 2), 4);
        assert_eq!(check(&[0., 0., 0., 1., 1.], 2), 5);
        assert_eq!(check(&[0., 0., 5e-6, 1., 1.], 2), 5);
        assert_eq!(check(&[0., 0., 5e-5, 1., 1.], 2), 0);
    }

    #[test]
    fn glu_check_order_of_tests() {
        // Too few knots and decreasing: 2 wins. Empty range and decreasing: 3 wins.
        assert_eq!(check(&[3., 2., 1.], 2), 2);
        assert_eq!(check(&[0., 1., 1., 0.5], 2), 3);
        let e: MathError = GluKnotError::TooFewKnots.into();
        assert_eq!(e, MathError::Knots("too few knots"));
        assert_eq!(GluKnotError::MultiplicityTooHigh.to_string(), "knot multiplicity greater than order of spline");
    }

    proptest! {
        #[test]
        fn find_span_never_panics_and_brackets(
            knots in prop::collection::vec(-10.0f64..10.0, 0..12),
            order in 0usize..6,
            u in prop::num::f64::ANY,
        ) {
            let mut sorted = knots.clone();
            sorted.sort_by(f64::total_cmp);
            let _ = find_span(&knots, order, u); // unsorted: only must not panic
            if let Some(i) = find_span(&sorted, order, u) {
                let n = sorted.len() - order;
                prop_assert!(i + 1 >= order && i < n);
                prop_assert!(sorted[i] <= u && u <= sorted[i + 1] && sorted[i] < sorted[i + 1]);
            }
        }

        #[test]
        fn generated_vectors_pass_glu((order, npts) in (1usize..8).prop_flat_map(|order| (Just(order), order..20))) {
            let u = KnotVector::<f32>::uniform(npts, order).unwrap();
            let o = KnotVector::<f32>::open_uniform(npts, order).unwrap();
            prop_assert_eq!(u.len(), npts + order);
            prop_assert_eq!(o.len(), npts + order);
            prop_assert!(u.glu_check(order).is_ok());
            prop_assert!(o.glu_check(order).is_ok());
            prop_assert_eq!(o.breakpoints(order).len(), npts - order + 2);
        }
    }
}
