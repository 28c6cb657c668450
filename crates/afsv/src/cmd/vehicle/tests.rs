//! Unit tests of `afsv vehicle`: where the seeds come from.
use super::*;

fn case(terrain: Option<&str>) -> CaseArgs {
    CaseArgs {
        load: Load::Loaded,
        speed_kmh: None,
        terrain: terrain.map(|t| terrain_arg(t).unwrap()),
        hps: Some("off".into()),
        vehicle: None,
        params: None,
        paper_form: false,
    }
}

#[test]
fn seeds_come_from_one_place() {
    let d = Some(TerrainSpec::default());
    let seeds = |c: &CaseArgs, n, s, d| terrain_and_seeds(c, n, s, d).map(|r| r.1);
    assert_eq!(
        seeds(&case(None), None, None, d).unwrap(),
        (1..=10).collect::<Vec<_>>()
    );
    assert_eq!(seeds(&case(None), Some(3), None, d).unwrap(), vec![1, 2, 3]);
    assert_eq!(seeds(&case(None), None, Some(7), d).unwrap(), vec![7]);
    assert_eq!(
        seeds(&case(Some("class:C,seed:4")), None, None, None).unwrap(),
        vec![4]
    );
    assert!(seeds(&case(Some("class:C,seed:4")), None, Some(4), d).is_err());
    assert!(seeds(&case(Some("class:C,seed:4")), Some(2), None, d).is_err());
    // smooth ground: one run, and seed options are refused
    let (t, s) = terrain_and_seeds(&case(None), None, None, None).unwrap();
    assert_eq!((t, s.len()), (None, 1));
    assert!(seeds(&case(Some("smooth")), Some(2), None, d).is_err());
    assert!(seeds(&case(None), None, Some(1), None).is_err());
    // an explicit terrain replaces the scenario's default
    let (t, _) = terrain_and_seeds(&case(Some("class:B")), None, None, d).unwrap();
    assert_eq!(t.unwrap().class, terrain_psd::IsoClass::B);
}
