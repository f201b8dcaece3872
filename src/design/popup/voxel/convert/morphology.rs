//! Small-bump removal of Mitani, Suzuki & Uno (2003) §3.2 a): morphological opening then closing of every x-slice (the yz
//! plane) with a square structuring element (3 × 3 in the paper; the side is adjustable).
//!
//! A slice of a depth field is a prefix image: row z is filled for `y < D(z)`. Erosion and
//! dilation by a square of half-side r keep that form, so both act on the profile D alone:
//! erosion is `min D − r` over the rows `z − r ..= z + r`, dilation `max D + r` (0 where the
//! rows are empty). Cells outside the slice — behind the back sheet, below the base, above the
//! top, past the base's front edge — are ignored: they neither erode nor dilate, so the back
//! sheet does not grow into the card and a row at the full depth `ny` stays there.

/// Opening then closing of one slice profile `d` (cells, at most `ny`) with a square element
/// of side `2r + 1`. `r = 0` leaves the profile unchanged.
pub(super) fn open_close(d: &mut [u16], ny: u16, r: usize) {
    if r == 0 || d.is_empty() {
        return;
    }
    let mut tmp = vec![0u16; d.len()];
    // Opening: erode, then dilate.
    erode(d, &mut tmp, ny, r);
    dilate(&tmp, d, ny, r);
    // Closing: dilate, then erode.
    dilate(d, &mut tmp, ny, r);
    erode(&tmp, d, ny, r);
}

fn window(len: usize, z: usize, r: usize) -> std::ops::Range<usize> {
    z.saturating_sub(r)..(z + r + 1).min(len)
}

fn erode(src: &[u16], dst: &mut [u16], ny: u16, r: usize) {
    for (z, out) in dst.iter_mut().enumerate() {
        let m = src[window(src.len(), z, r)]
            .iter()
            .copied()
            .min()
            .unwrap_or(0);
        *out = if m >= ny {
            ny
        } else {
            m.saturating_sub(r as u16)
        };
    }
}

fn dilate(src: &[u16], dst: &mut [u16], ny: u16, r: usize) {
    for (z, out) in dst.iter_mut().enumerate() {
        let m = src[window(src.len(), z, r)]
            .iter()
            .copied()
            .max()
            .unwrap_or(0);
        *out = if m == 0 {
            0
        } else {
            (m as usize + r).min(ny as usize) as u16
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Opening and closing done on the explicit binary slice image, for comparison.
    fn image_open_close(d: &[u16], ny: u16, r: usize) -> Vec<u16> {
        let (nz, ny_) = (d.len() as i64, ny as i64);
        let img: Vec<Vec<bool>> = d
            .iter()
            .map(|&v| (0..ny_).map(|y| y < v as i64).collect())
            .collect();
        let op = |img: &Vec<Vec<bool>>, all: bool| -> Vec<Vec<bool>> {
            let mut out = img.clone();
            for z in 0..nz {
                for y in 0..ny_ {
                    let mut vals = Vec::new();
                    for dz in -(r as i64)..=r as i64 {
                        for dy in -(r as i64)..=r as i64 {
                            let (zz, yy) = (z + dz, y + dy);
                            // Cells outside the slice are ignored.
                            if (0..nz).contains(&zz) && (0..ny_).contains(&yy) {
                                vals.push(img[zz as usize][yy as usize]);
                            }
                        }
                    }
                    out[z as usize][y as usize] = if all {
                        vals.iter().all(|&v| v)
                    } else {
                        vals.iter().any(|&v| v)
                    };
                }
            }
            out
        };
        let opened = op(&op(&img, true), false);
        let closed = op(&op(&opened, false), true);
        closed
            .iter()
            .map(|row| row.iter().take_while(|&&v| v).count() as u16)
            .collect()
    }

    #[test]
    fn profile_ops_equal_image_ops() {
        let profiles: [&[u16]; 5] = [
            &[0, 0, 5, 5, 5, 0, 0, 0],
            &[8, 8, 1, 8, 8, 8, 2, 2, 2, 0],
            &[3, 6, 3, 3, 7, 7, 7, 1, 1, 1, 1],
            &[8, 8, 8, 8],
            &[2, 0, 2, 0, 2, 5, 5, 5, 5, 5, 5],
        ];
        for d in profiles {
            for r in 1..=2 {
                let mut ours = d.to_vec();
                open_close(&mut ours, 8, r);
                assert_eq!(ours, image_open_close(d, 8, r), "profile {d:?}, r {r}");
            }
        }
    }

    #[test]
    fn a_one_row_ledge_is_removed_and_a_one_row_notch_filled() {
        let mut ledge = vec![4, 4, 4, 6, 4, 4, 4];
        open_close(&mut ledge, 10, 1);
        assert_eq!(ledge, vec![4; 7]);
        let mut notch = vec![4, 4, 4, 2, 4, 4, 4];
        open_close(&mut notch, 10, 1);
        assert_eq!(notch, vec![4; 7]);
        let mut wide = vec![4, 4, 6, 6, 6, 4, 4];
        open_close(&mut wide, 10, 1);
        assert_eq!(
            wide,
            vec![4, 4, 6, 6, 6, 4, 4],
            "a 3-row ledge survives a 3 × 3 element"
        );
    }
}
