//! Tool nose radius compensation on the lathe (behaviour 18): the
//! imaginary tool nose and its direction. The lathe runs the mill's
//! compensation C (this family's `geometry.rs`) in the ZX plane, X as a
//! radius; what is the lathe's own is here: where the point the program
//! follows lies from the nose centre, by the tip direction 0–9 of the
//! offset register (Fanuc 0i-TF / 30i-TB operator's manuals, "Tool nose
//! radius compensation", "Imaginary tool nose" and "Direction of imaginary
//! tool nose"; Haas lathe operator's manual, "Tool Nose Compensation", the
//! tool tip directions figure).

/// Where the imaginary tool nose lies from the nose centre, per unit of the
/// nose radius, as plane coordinates (Z, X radius), for tip direction `t`
/// (behaviour 18.2). The manuals draw the directions with +X up and +Z to
/// the right (the rear tool post, the Fanuc figure's first case and the
/// Haas figure): 1 to 4 the corners — 3 the outside turning tool cutting
/// toward the chuck, its imaginary nose below and left of the centre; 2 the
/// boring bar, above and left — and 5 to 8 the axis directions (+Z, +X,
/// −Z, −X). 0 and 9: the program follows the nose centre itself.
pub fn tip_vector(t: u8) -> [f64; 2] {
    match t {
        1 => [1.0, 1.0],
        2 => [-1.0, 1.0],
        3 => [-1.0, -1.0],
        4 => [1.0, -1.0],
        5 => [1.0, 0.0],
        6 => [0.0, 1.0],
        7 => [-1.0, 0.0],
        8 => [0.0, -1.0],
        _ => [0.0, 0.0],
    }
}

/// "the imaginary tool nose (tip 3)" or "the nose centre (tip 0)": the
/// point the program follows.
pub fn follows(t: u8) -> String {
    if tip_vector(t) == [0.0, 0.0] {
        format!("the nose centre (tip {t})")
    } else {
        format!("the imaginary tool nose (tip {t})")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn behaviour18_2_tips_1_to_4_are_the_corners_5_to_8_the_axes_0_and_9_the_centre() {
        // Tip 3, the outside turning tool: the imaginary nose is the corner
        // of the square round the nose circle at −Z and −X.
        assert_eq!(tip_vector(3), [-1.0, -1.0]);
        // Tip 2, the boring bar toward the chuck: −Z and +X.
        assert_eq!(tip_vector(2), [-1.0, 1.0]);
        assert_eq!(tip_vector(8), [0.0, -1.0]);
        assert_eq!(tip_vector(0), [0.0, 0.0]);
        assert_eq!(tip_vector(9), [0.0, 0.0]);
        // Opposite corners and opposite axes are opposite vectors.
        for (a, b) in [(1, 3), (2, 4), (5, 7), (6, 8)] {
            let (u, v) = (tip_vector(a), tip_vector(b));
            assert_eq!([u[0] + v[0], u[1] + v[1]], [0.0, 0.0]);
        }
        assert_eq!(follows(0), "the nose centre (tip 0)");
        assert_eq!(follows(3), "the imaginary tool nose (tip 3)");
    }
}
