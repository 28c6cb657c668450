//! Fuzz cases of the optimisation across processes: `afsv optimize layout` and the shard
//! evaluation of a batch file, `afsv batch evaluate`.

use super::super::gen::*;

/// The options of one `afsv optimize layout` case: always one value it must refuse, since a
/// valid problem runs a genetic algorithm over 3-D vehicle runs.
pub(super) fn optimize_layout_case(g: &mut Gen<'_>) {
    let bad_slot = g.rng.below(5);
    // which option slot 3 makes bad (4: the D4 speeds, read with the d4_speed objective)
    let bad_option = g.rng.below(5);
    let vary = if bad_slot == 0 {
        g.rng
            .pick(&[
                "bogus=1..2",
                "front.a_b=3e-5..5e-6",
                "front.a_b",
                "",
                "front.a_b=5e-6..1e3",
                "front.a_b=nan..3e-5",
                "front.a_b=-inf..3e-5",
                "a_b=5e-6..3e-5",
                "front.a_b=5e-6..3e-5,rear.a_b=5e-6..3e-5",
                "seat.bogus=1..2",
                "seat.damping_n_s_per_m=2000..200",
                "seat.travel_m=0.001..0.2",
                "cab.mounts[9].x_m=0..1",
                "seat.cushion.stiffness_n_per_m=1e4..2e4",
            ])
            .to_string()
    } else {
        "front.a_b=5e-6..3e-5".to_string()
    };
    g.push_opt("--vary", &vary);
    if bad_slot == 0 && g.rng.chance(0.3) {
        // without a cab and seat, a `seat.`/`cab.` variable is refused like any bad one
        g.push_opt("--seat", "off");
    }
    let objective = if bad_slot == 1 {
        g.rng
            .pick(&["bogus", "", "awz", "awz_seat,seat"])
            .to_string()
    } else if bad_slot == 3 && bad_option == 4 {
        "d4_speed".to_string()
    } else {
        "awz_seat".to_string()
    };
    g.push_opt("--objective", &objective);
    if bad_slot == 2 {
        let c = g
            .rng
            .pick(&[
                "awz < 0.5",
                "bogus <= 1",
                "awz_seat <= 2 * 3",
                "",
                "<= 1",
                "awz_seat <= nan",
                "awz_seat <= -inf",
                "sp_drt >= 0 * nominal",
                "sp_drt >= -1 * nominal",
            ])
            .to_string();
        g.push_opt("--constraint", &c);
    }
    if bad_slot == 3 {
        let (flag, v) = match bad_option {
            0 => (
                "--population",
                g.rng.pick(&["3", "5", "0", "-4", "1e9", "x"]),
            ),
            1 => ("--generations", g.rng.pick(&["0", "-1", "1001", "x"])),
            2 => ("--seeds", g.rng.pick(&["0", "101", "-1", "x"])),
            4 => (
                "--d4-speeds",
                g.rng
                    .pick(&["30,20", "20", "x", "20,2e9", "20,20", "nan,30", ""]),
            ),
            _ => ("--speed-kmh", g.rng.pick(&["0", "nan", "1e308", "-20"])),
        };
        g.push_opt(flag, v);
    } else {
        g.push_opt("--population", "4");
        g.push_opt("--generations", "1");
    }
    if bad_slot == 4 {
        let l = g
            .rng
            .pick(&["bogus", "", "rigid,front-hps", "front-rear-hps,"])
            .to_string();
        g.push_opt("--layout", &l);
    }
    if g.rng.chance(0.3) {
        g.file("state.json", b"{\"mine\": true}\n".to_vec());
        g.push_opt("--state", "state.json");
        let o = g.output("batch.jsonl", &["state.json"]);
        g.push_opt("--ask", &o);
    }
}

/// A batch file of `afsv optimize afs --ask` (header and two points), one line of it
/// broken or a number replaced by a bad value, and a good or bad `--shard`.
const BATCH_LINES: [&str; 3] = [
    r#"{"format":"afsv-batch","version":2,"written_by":"afsv optimize afs --ask","sign_convention":"afsv-v1","batch":0,"state_sha256":"5f2b0c6e9a4d8e1f3c7b2a6d9e0f4a8b1c5d9e2f6a0b4c8d3e7f1a5b9c2d6e0f","finished":false,"points":2,"variables":["a0_rad","l1_m","l2_m","valve_av","bulk_modulus_pa"],"problems":[{"kind":"afs_chapter4","label":"with the steering-arm constraint","relaxed":false,"min_steering_arm_m":0.25,"rtol":1e-8,"form":"energy_consistent","eq_4_9":null}]}"#,
    r#"{"id":"b0-0","problem":0,"phase":"start_point","screened":true,"x":{"a0_rad":1.335176877775662,"bulk_modulus_pa":1600000000.0,"l1_m":1.96,"l2_m":0.64,"valve_av":8e-10}}"#,
    r#"{"id":"b0-1","problem":0,"phase":"sqp","screened":false,"x":{"a0_rad":1.0,"bulk_modulus_pa":1700000000.0,"l1_m":2.0,"l2_m":0.9,"valve_av":1.2e-9}}"#,
];

/// The options and files of one `afsv batch evaluate` case.
pub(super) fn batch_case(g: &mut Gen<'_>) {
    let mut lines: Vec<String> = BATCH_LINES.iter().map(|l| l.to_string()).collect();
    if g.rng.chance(0.8) {
        let k = g.rng.below(lines.len());
        lines[k] = mutate_json(&mut g.rng, &lines[k]).replace('\n', "");
    }
    if g.rng.chance(0.1) {
        lines.push(lines[1].clone());
    }
    g.file("batch.jsonl", (lines.join("\n") + "\n").into_bytes());
    g.arg("batch.jsonl");
    if g.rng.chance(0.6) {
        let shard = match g.rng.below(4) {
            0 => g.bad(),
            1 => g
                .rng
                .pick(&["0/2", "3/2", "1/0", "1/1000000", "2/2/2", "/", "a/b"])
                .to_string(),
            _ => g.rng.pick(&["1/2", "2/2", "1/1"]).to_string(),
        };
        g.push_opt("--shard", &shard);
    }
    let o = g.output("results.jsonl", &["batch.jsonl"]);
    g.push_opt("-o", &o);
}
