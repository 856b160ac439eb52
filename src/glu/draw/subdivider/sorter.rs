//! GLU's own quicksort (`Sorter::qs1`, `internals/sorter.cc`, the Unix V7 `qsort`): arcs that
//! compare equal, or inconsistently, end up where this algorithm puts them, so the order GLU
//! joins arcs in is only reproduced by the same algorithm.

/// Sorts `v` by `cmp` (negative, zero or positive) exactly as `Sorter::qsort` does.
pub(crate) fn qsort<T: Copy>(v: &mut [T], cmp: &mut dyn FnMut(T, T) -> i32) {
    qs1(v, 0, v.len(), cmp);
}

fn qs1<T: Copy>(v: &mut [T], mut a: usize, mut l: usize, cmp: &mut dyn FnMut(T, T) -> i32) {
    // `qstexc(i, j, k)`: i <- k, k <- j, j <- i.
    let rotate = |v: &mut [T], i: usize, j: usize, k: usize| {
        let t = v[i];
        v[i] = v[k];
        v[k] = v[j];
        v[j] = t;
    };
    'start: loop {
        if l - a <= 1 {
            return;
        }
        let (mut lp, mut hp) = (a + (l - a) / 2, a + (l - a) / 2);
        let (mut i, mut j) = (a, l - 1);
        'outer: loop {
            if i < lp {
                let c = cmp(v[i], v[lp]);
                if c == 0 {
                    lp -= 1;
                    v.swap(i, lp);
                    continue;
                }
                if c < 0 {
                    i += 1;
                    continue;
                }
            }
            while j > hp {
                let c = cmp(v[hp], v[j]);
                if c == 0 {
                    hp += 1;
                    v.swap(hp, j);
                    continue;
                }
                if c > 0 {
                    if i == lp {
                        hp += 1;
                        rotate(v, i, hp, j);
                        lp += 1;
                        i = lp;
                        continue;
                    }
                    v.swap(i, j);
                    j -= 1;
                    i += 1;
                    continue 'outer;
                }
                j -= 1;
            }
            if i == lp {
                if lp - a >= l - hp {
                    qs1(v, hp + 1, l, cmp);
                    l = lp;
                } else {
                    qs1(v, a, lp, cmp);
                    a = hp + 1;
                }
                continue 'start;
            }
            lp -= 1;
            rotate(v, j, lp, i);
            hp -= 1;
            j = hp;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorts_like_any_sort_when_keys_differ() {
        let mut v = [5, 3, 9, 1, 7, 2, 8, 6, 4, 0];
        qsort(&mut v, &mut |a: i32, b: i32| a - b);
        assert_eq!(v, [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]);
        let mut one = [1];
        qsort(&mut one, &mut |a: i32, b: i32| a - b);
        let mut none: [i32; 0] = [];
        qsort(&mut none, &mut |a: i32, b: i32| a - b);
    }

    #[test]
    fn an_inconsistent_comparison_still_ends() {
        let mut v = [3, 1, 2, 5, 4];
        qsort(&mut v, &mut |_, _| 1);
        qsort(&mut v, &mut |_, _| -1);
        qsort(&mut v, &mut |_, _| 0);
    }
}
