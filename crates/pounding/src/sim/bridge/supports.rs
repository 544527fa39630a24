//! A bridge's support lines ([`SupportLine`]): where each support stands and which line each
//! bearing stands on, for motions that differ per support ([`crate::sim::excitation`]).

use super::BridgeModel;
use crate::math::Real;
use crate::sim::excitation::SupportLine;

impl BridgeModel {
    /// The bridge's support lines, in order along the chain (module doc).
    pub fn support_lines(&self) -> Vec<SupportLine> {
        let bodies = self.layout();
        let n = bodies.len();
        let mut out = Vec::with_capacity(n + 1);
        for s in 0..=n {
            let (id, position) = match s {
                0 => ("start".to_string(), bodies[0].start.mid),
                s if s == n => ("end".to_string(), bodies[n - 1].end.mid),
                s => (
                    format!("joint{s}"),
                    (bodies[s - 1].end.mid + bodies[s].start.mid) * 0.5,
                ),
            };
            out.push(SupportLine { id, position });
        }
        out
    }

    /// Each support line's id and its distance \[m\] from the `start` line along the default
    /// direction of a wave (from the `start` line toward the `end` one): the positions of
    /// `pounding motion svgm --bridge`.
    pub fn support_distances(&self) -> Vec<(String, Real)> {
        let lines = self.support_lines();
        let (p0, p1) = (lines[0].position, lines[lines.len() - 1].position);
        let e = (p1 - p0) / (p1 - p0).norm();
        lines
            .into_iter()
            // to the nanometre: the layout's sums leave rounding in the last digits
            .map(|l| (l.id, ((l.position - p0).dot(&e) * 1e9).round() / 1e9))
            .collect()
    }

    /// The support line under each bearing of each segment: the line of the segment end it
    /// belongs to (the nearer one).
    pub(crate) fn bearing_lines(&self) -> Vec<Vec<usize>> {
        let bodies = self.layout();
        self.bearing_points()
            .iter()
            .enumerate()
            .map(|(i, pts)| {
                let b = &bodies[i];
                pts.iter()
                    .map(|p| {
                        let ds = (p - b.start.mid).dot(&b.start.inward).abs();
                        let de = (p - b.end.mid).dot(&b.end.inward).abs();
                        if ds <= de { i } else { i + 1 }
                    })
                    .collect()
            })
            .collect()
    }
}
