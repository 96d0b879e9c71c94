//! The vertices of a path in backend pixels that shape it: a curve sampled finer than the
//! pixels it crosses repeats points and runs along straight rows (a response that has died
//! out, a clipped peak), and each vertex is one call from wasm to the canvas.

/// A point in backend pixels.
type Px = (i32, i32);

/// Passes to `emit` the vertices of the path through `points` that change its shape: the
/// first, the last, and every point where it turns. Dropped are repeats of the point
/// before and points on the straight segment from the last kept point to the next one,
/// so the stroked or filled path is the same.
pub fn corners(points: impl IntoIterator<Item = Px>, mut emit: impl FnMut(Px)) {
    let mut points = points.into_iter();
    let Some(mut kept) = points.next() else {
        return;
    };
    emit(kept);
    // The point after `kept`, not yet known to be a corner.
    let mut open: Option<Px> = None;
    for next in points {
        match open {
            Some(p) if p == next => {}
            None if next == kept => {}
            None => open = Some(next),
            Some(p) if on_segment(kept, p, next) => open = Some(next),
            Some(p) => {
                emit(p);
                (kept, open) = (p, Some(next));
            }
        }
    }
    if let Some(p) = open {
        emit(p);
    }
}

/// Whether `b` lies on the segment from `a` to `c`, strictly inside it: the turn at `b`
/// is zero (cross product) and the path goes on in the same direction (dot product).
fn on_segment(a: Px, b: Px, c: Px) -> bool {
    let (ux, uy) = (i64::from(b.0 - a.0), i64::from(b.1 - a.1));
    let (vx, vy) = (i64::from(c.0 - b.0), i64::from(c.1 - b.1));
    ux * vy == uy * vx && ux * vx + uy * vy > 0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kept(points: &[Px]) -> Vec<Px> {
        let mut out = Vec::new();
        corners(points.iter().copied(), |p| out.push(p));
        out
    }

    #[test]
    fn straight_runs_and_repeats_keep_only_their_ends() {
        let flat: Vec<Px> = (0..50).map(|x| (x, 7)).collect();
        assert_eq!(kept(&flat), [(0, 7), (49, 7)]);
        let diagonal: Vec<Px> = (0..20).map(|i| (2 * i, 3 * i)).collect();
        assert_eq!(kept(&diagonal), [(0, 0), (38, 57)]);
        assert_eq!(kept(&[(1, 1), (1, 1), (1, 1)]), [(1, 1)]);
        assert_eq!(
            kept(&[(1, 1), (1, 1), (4, 1), (4, 1), (9, 1)]),
            [(1, 1), (9, 1)]
        );
        assert!(kept(&[]).is_empty());
    }

    #[test]
    fn every_turn_and_every_reversal_is_kept() {
        // Up, across, down: two corners.
        let path = [(0, 0), (0, 5), (0, 10), (5, 10), (10, 10), (10, 5)];
        assert_eq!(kept(&path), [(0, 0), (0, 10), (10, 10), (10, 5)]);
        // Along a row and back: the far end is a vertex even though it is collinear.
        assert_eq!(kept(&[(0, 0), (10, 0), (3, 0)]), [(0, 0), (10, 0), (3, 0)]);
        // A sampled curve keeps every point where its slope changes.
        let curve: Vec<Px> = (0..30).map(|x| (x, (x * x) / 10)).collect();
        let out = kept(&curve);
        assert_eq!(out.first(), Some(&(0, 0)));
        assert_eq!(out.last(), Some(&(29, 84)));
        assert!(out.len() < curve.len());
        // Whatever was dropped lies on the segment between the vertices around it.
        let mut last = 0; // index in `out` of the last vertex passed
        for p in &curve {
            if out.get(last + 1) == Some(p) {
                last += 1;
            } else if out[last] != *p {
                let (a, c) = (out[last], out[last + 1]);
                assert!(on_segment(a, *p, c), "{p:?} is not on {a:?}–{c:?}");
            }
        }
    }
}
