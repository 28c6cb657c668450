//! The one scheduler of the design studies on the 3-D vehicle: per terrain case a cache
//! that does not depend on the design (the tires' enveloping tracks of a seed and load),
//! built once in parallel and shared by every run that drives over it, then every run in
//! parallel ([`cached`]); and the plain fan-out of one run per terrain seed ([`over_seeds`]).
//! Results come back in the order of the inputs, so a study's numbers do not depend on
//! the thread count.

use rayon::prelude::*;

/// Builds `build(case)` for every case in parallel (the first error in the cases' order
/// stops the study), then runs `run(job, caches)` for every job in parallel, calling
/// `done(job)` after each; the runs' results in the jobs' order. A run's failure is its
/// result (`R` may be a `Result`): the caller decides whether it stops the study.
pub fn cached<C, K, E, J, R>(
    cases: &[C],
    build: impl Fn(&C) -> Result<K, E> + Sync,
    jobs: &[J],
    run: impl Fn(&J, &[K]) -> R + Sync,
    done: impl Fn(&J) + Sync,
) -> Result<Vec<R>, E>
where
    C: Sync,
    K: Send + Sync,
    E: Send,
    J: Sync,
    R: Send,
{
    let caches: Vec<K> = cases
        .par_iter()
        .map(&build)
        .collect::<Vec<_>>()
        .into_iter()
        .collect::<Result<_, E>>()?;
    Ok(jobs
        .par_iter()
        .map(|j| {
            let r = run(j, &caches);
            done(j);
            r
        })
        .collect())
}

/// The `n` terrain seeds from `first` on (`first`, `first + 1`, ..., wrapping at the end of
/// `u64`): the common seeds of every study.
pub fn seed_range(first: u64, n: u64) -> Vec<u64> {
    (0..n).map(|i| first.wrapping_add(i)).collect()
}

/// Runs `one(index, seed)` for every seed in parallel, calling `done(seed)` after each;
/// the results in the seeds' order, or the first failure in that order.
pub fn over_seeds<T: Send, E: Send>(
    seeds: &[u64],
    one: impl Fn(usize, u64) -> Result<T, E> + Sync,
    done: impl Fn(u64) + Sync,
) -> Result<Vec<T>, E> {
    seeds
        .par_iter()
        .enumerate()
        .map(|(i, &s)| {
            let r = one(i, s);
            done(s);
            r
        })
        .collect::<Vec<_>>()
        .into_iter()
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn seed_ranges_count_up_from_the_first_and_wrap() {
        assert_eq!(seed_range(3, 3), [3, 4, 5]);
        assert_eq!(seed_range(u64::MAX, 2), [u64::MAX, 0]);
        assert!(seed_range(1, 0).is_empty());
    }

    #[test]
    fn caches_are_built_once_per_case_and_results_keep_the_jobs_order() {
        let built = AtomicUsize::new(0);
        let ran = AtomicUsize::new(0);
        let cases = [10u64, 20, 30];
        let jobs: Vec<(usize, u64)> = (0..40).map(|j| (j % 3, j as u64)).collect();
        let out = cached(
            &cases,
            |c| {
                built.fetch_add(1, Ordering::Relaxed);
                Ok::<u64, String>(c * 2)
            },
            &jobs,
            |&(c, j), k| k[c] + j,
            |_| {
                ran.fetch_add(1, Ordering::Relaxed);
            },
        )
        .unwrap();
        assert_eq!(built.load(Ordering::Relaxed), 3);
        assert_eq!(ran.load(Ordering::Relaxed), 40);
        let want: Vec<u64> = jobs.iter().map(|&(c, j)| cases[c] * 2 + j).collect();
        assert_eq!(out, want);
        let e = cached(
            &cases,
            |&c| if c >= 20 { Err(c) } else { Ok(c) },
            &jobs,
            |_, _| 0,
            |_| {},
        )
        .unwrap_err();
        assert_eq!(e, 20, "the first failing case in order");
    }

    #[test]
    fn seeds_come_back_in_order_and_the_first_failure_wins() {
        let seen = AtomicUsize::new(0);
        let seeds: Vec<u64> = (1..=12).collect();
        let out = over_seeds(
            &seeds,
            |i, s| Ok::<_, String>((i, s * s)),
            |_| {
                seen.fetch_add(1, Ordering::Relaxed);
            },
        )
        .unwrap();
        assert_eq!(seen.load(Ordering::Relaxed), 12);
        assert!(out
            .iter()
            .enumerate()
            .all(|(i, &(j, v))| i == j && v == seeds[i] * seeds[i]));
        let e = over_seeds(
            &seeds,
            |_, s| if s % 5 == 0 { Err(s) } else { Ok(s) },
            |_| {},
        )
        .unwrap_err();
        assert_eq!(e, 5);
    }
}
