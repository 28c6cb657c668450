//! Tabular results follow one rule: `-o FILE.csv` writes every row as CSV with an afsv
//! sidecar and prints a summary; a pipe (or `--json`) gets the whole result as JSON; a
//! foreign file is not replaced without `--force`.

mod cli_support;
use afsv_records::Record;
use cli_support::{afsv, json, scratch};

#[test]
fn tire_terrain_and_strut_tables_write_csv() {
    let csv = scratch("tables", "sweep.csv");
    let v = json(&afsv(&[
        "tire",
        "sweep",
        "--fz",
        "50000:150000:50000",
        "--alpha-deg",
        "-10:10:1",
        "-o",
        csv.to_str().unwrap(),
    ]));
    assert_eq!(v["rows"], 63, "{v}");
    let rec = Record::read(&csv).unwrap();
    assert_eq!(
        rec.names(),
        [
            "fz_n",
            "kappa",
            "alpha_deg",
            "fx_n",
            "fy_n",
            "mz_nm",
            "my_nm"
        ]
    );
    assert_eq!(rec.meta["written_by"], "afsv tire sweep");
    // The sidecar's provenance: the tool, its version, the commit (or why there is none)
    // and the inputs read.
    let p = &rec.meta["provenance"];
    assert_eq!(p["tool"], "afsv");
    assert_eq!(p["version"], env!("CARGO_PKG_VERSION"));
    assert!(p["inputs"].is_array(), "{p}");
    assert!(
        p["commit"].is_string() || p["commit_reason"].is_string(),
        "{p}"
    );
    // The JSON of a pipe holds the same numbers.
    let rows = json(&afsv(&[
        "tire",
        "sweep",
        "--fz",
        "50000:150000:50000",
        "--alpha-deg",
        "-10:10:1",
    ]));
    let fy: Vec<f64> = rows
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["fy_n"].as_f64().unwrap())
        .collect();
    assert_eq!(rec.column("fy_n").unwrap(), fy.as_slice());

    // A profile, its PSD and its enveloped profile.
    let prof = scratch("tables", "prof.csv");
    json(&afsv(&[
        "terrain",
        "generate",
        "--class",
        "C",
        "--length",
        "100",
        "-o",
        prof.to_str().unwrap(),
    ]));
    let psd = scratch("tables", "psd.csv");
    let v = json(&afsv(&[
        "terrain",
        "psd",
        "-i",
        prof.to_str().unwrap(),
        "-o",
        psd.to_str().unwrap(),
    ]));
    let rec = Record::read(&psd).unwrap();
    assert_eq!(rec.len() as u64, v["rows"].as_u64().unwrap());
    for c in [
        "n_cycles_per_m",
        "psd_left_m3",
        "coherence",
        "target_psd_m3",
    ] {
        assert!(rec.column(c).is_some(), "{c} in {:?}", rec.names());
    }
    let env = scratch("tables", "env.csv");
    json(&afsv(&[
        "tire",
        "envelope",
        "--profile",
        prof.to_str().unwrap(),
        "-o",
        env.to_str().unwrap(),
    ]));
    let rec = Record::read(&env).unwrap();
    assert_eq!(rec.names()[0], "x_m");
    assert_eq!(rec.len(), Record::read(&prof).unwrap().len());

    let ch = scratch("tables", "char.csv");
    json(&afsv(&[
        "hps",
        "characterize",
        "--quiet",
        "-o",
        ch.to_str().unwrap(),
    ]));
    let rec = Record::read(&ch).unwrap();
    assert_eq!(rec.names()[..2], ["frequency_hz", "amplitude_m"]);
    assert_eq!(rec.meta["strut"], "lab-1orifice");
}

#[test]
fn a_foreign_file_is_kept_without_force() {
    let csv = scratch("tables", "mine.csv");
    std::fs::write(&csv, "my,own\n1,2\n").unwrap();
    let out = afsv(&["tire", "sweep", "--fz", "1e5", "-o", csv.to_str().unwrap()]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--force"));
    assert_eq!(std::fs::read_to_string(&csv).unwrap(), "my,own\n1,2\n");
    json(&afsv(&[
        "tire",
        "sweep",
        "--fz",
        "1e5",
        "-o",
        csv.to_str().unwrap(),
        "--force",
    ]));
    assert!(Record::read(&csv).unwrap().column("fy_n").is_some());
}
