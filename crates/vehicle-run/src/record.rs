//! A run's record as named columns: the channels a vehicle names, in its order.

/// The columns `names` of a run, in order, each read by `channel` (a name it does not know
/// is left out).
pub fn columns(
    names: &[&'static str],
    channel: impl Fn(&str) -> Option<Vec<f64>>,
) -> Vec<(&'static str, Vec<f64>)> {
    names
        .iter()
        .filter_map(|&name| Some((name, channel(name)?)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_columns_keep_the_order_and_leave_out_unknown_names() {
        let c = columns(&["b_m", "nope", "a_m"], |n| match n {
            "a_m" => Some(vec![1.0]),
            "b_m" => Some(vec![2.0]),
            _ => None,
        });
        assert_eq!(c, [("b_m", vec![2.0]), ("a_m", vec![1.0])]);
    }
}
