//! Print the measured-vs-target summary of the paper's nominal terrain as JSON.
//! `cargo run --release -p terrain-psd --example terrain_summary -- [SEED]`
fn main() {
    let seed = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    let s = terrain_psd::default_terrain_summary(seed);
    println!(
        "{}",
        serde_json::to_string_pretty(&s).expect("summary serialises")
    );
}
