//! `cargo xtask slurm-test`: a real single-node Slurm on this machine runs
//! `scripts/slurm/optimize.sh` end to end for two problems, and each report must equal the
//! in-process run with the same options, byte for byte (wall-clock times left out): the
//! reduced chapter-4 `afsv optimize afs` and a tiny `afsv optimize layout` (the prototype's
//! front and rear HPS with the generic seat, both bleed orifices varied, the front strut
//! travel minimised with a seat constraint; 4 batches of at most 4 designs, ~10 s).
//!
//! As root it installs Debian's `slurm-wlm` and `munge` (apt-get, non-interactive) unless
//! they are there, writes a minimal `slurm.conf` into a temporary folder (one node named
//! after `hostname -s` with the CPUs of this machine, `select/cons_tres`,
//! `proctrack/linuxproc`, `task/none`, no accounting, state and spool folders inside the
//! temporary folder, ports 16817/16818, `MinJobAge=4` so that `sbatch --wait` polls every
//! 2 s), creates a munge key, starts munged (as the `munge` user), slurmctld and slurmd in
//! the foreground as its own children, waits for the node to be idle, runs the script,
//! compares, and stops the three daemons by their process ids. Without root, apt-get or
//! the network it prints why and "skipped", and succeeds. `--bin PATH` runs that `afsv`
//! binary instead of building one with `cargo build -p afsv --release` (CI passes the
//! binary of its one release build: `-p afsv` resolves dependency features apart from the
//! workspace build and would compile the whole dependency tree a second time).

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// The reduced chapter-4 run (the one of `crates/afsv/tests/cli_cluster.rs`): 20 batches.
const OPTIONS: &str =
    "--starts 0 --search-points 5 --screen-mesh 0.125 --min-mesh 0.0625 --sqp-calls 3";

/// The tiny layout run (the one of `crates/afsv/tests/cli_optimize_layout.rs`): a
/// two-axle HPS layout with a seat constraint, 4 batches (the nominal, the initial
/// population of 4, two generations).
const LAYOUT_OPTIONS: &str = "--vary front.a_b=5e-6..3e-5 --vary rear.a_b=5e-6..3e-5 \
    --objective strut_travel --constraint awz_seat<=1.1*nominal --speed-kmh 30 \
    --ride-length-m 15 --population 4 --generations 2 --seed 7";

/// The daemons this task started; stopped (SIGTERM, then SIGKILL) when dropped.
struct Daemons(Vec<(&'static str, Child)>);

impl Drop for Daemons {
    fn drop(&mut self) {
        // slurmd first, munged last.
        for (name, child) in self.0.iter_mut().rev() {
            let pid = child.id().to_string();
            let _ = Command::new("kill").args(["-TERM", &pid]).status();
            let deadline = Instant::now() + Duration::from_secs(10);
            while Instant::now() < deadline {
                if let Ok(Some(_)) = child.try_wait() {
                    break;
                }
                std::thread::sleep(Duration::from_millis(100));
            }
            if let Ok(None) = child.try_wait() {
                eprintln!("slurm-test: {name} (pid {pid}) did not stop on SIGTERM; killing it");
                let _ = child.kill();
                let _ = child.wait();
            }
        }
    }
}

fn have(program: &str) -> bool {
    Command::new("sh")
        .args(["-c", &format!("command -v {program}")])
        .stdout(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

fn output(cmd: &mut Command) -> Result<String, String> {
    let out = cmd.output().map_err(|e| format!("{cmd:?}: {e}"))?;
    if out.status.success() {
        Ok(String::from_utf8_lossy(&out.stdout).trim().to_string())
    } else {
        Err(format!(
            "{cmd:?}: {}: {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        ))
    }
}

/// Why Slurm cannot be run here, or `None` once its programs are installed (as root).
fn install() -> Option<String> {
    match output(Command::new("id").arg("-u")) {
        Ok(uid) if uid == "0" => {}
        Ok(_) => return Some("not root: the daemons and the package install need root".into()),
        Err(e) => return Some(format!("cannot tell the user id: {e}")),
    }
    let needed = ["munged", "munge", "slurmctld", "slurmd", "sbatch", "sinfo"];
    if needed.iter().all(|p| have(p)) {
        return None;
    }
    if !have("apt-get") {
        return Some("no apt-get: cannot install slurm-wlm and munge".into());
    }
    let apt = |args: &[&str]| {
        Command::new("apt-get")
            .args(args)
            .env("DEBIAN_FRONTEND", "noninteractive")
            .stdout(Stdio::null())
            .output()
    };
    let get = [
        "install",
        "-y",
        "-q",
        "--no-install-recommends",
        "slurm-wlm",
        "munge",
    ];
    eprintln!("slurm-test: apt-get install slurm-wlm munge");
    let mut last = apt(&get);
    if !last.as_ref().is_ok_and(|o| o.status.success()) {
        eprintln!("slurm-test: apt-get update, then install again");
        let _ = apt(&["update", "-q"]);
        last = apt(&get);
    }
    match last {
        Ok(o) if o.status.success() && needed.iter().all(|p| have(p)) => None,
        Ok(o) => Some(format!(
            "apt-get install slurm-wlm munge failed (network down?): {}",
            String::from_utf8_lossy(&o.stderr)
                .lines()
                .last()
                .unwrap_or("")
        )),
        Err(e) => Some(format!("cannot run apt-get: {e}")),
    }
}

fn spawn(
    name: &'static str,
    cmd: &mut Command,
    log: &Path,
) -> Result<(&'static str, Child), String> {
    let file = std::fs::File::create(log).map_err(|e| format!("{}: {e}", log.display()))?;
    let err = file.try_clone().map_err(|e| e.to_string())?;
    let child = cmd
        .stdin(Stdio::null())
        .stdout(file)
        .stderr(err)
        .spawn()
        .map_err(|e| format!("cannot start {name}: {e}"))?;
    Ok((name, child))
}

/// Polls `ready` every 200 ms for at most `secs` seconds.
fn wait_for(what: &str, secs: u64, ready: &mut dyn FnMut() -> bool) -> Result<(), String> {
    let deadline = Instant::now() + Duration::from_secs(secs);
    while Instant::now() < deadline {
        if ready() {
            return Ok(());
        }
        std::thread::sleep(Duration::from_millis(200));
    }
    Err(format!("{what} not ready after {secs} s"))
}

fn slurm_conf(dir: &Path, host: &str, cpus: usize) -> String {
    let d = dir.display();
    format!(
        "ClusterName=afsvtest\n\
         SlurmctldHost={host}\n\
         SlurmctldPort=16817\n\
         SlurmdPort=16818\n\
         AuthType=auth/munge\n\
         AuthInfo=socket={d}/munge/munge.socket\n\
         CredType=cred/munge\n\
         SlurmUser=root\n\
         SlurmdUser=root\n\
         StateSaveLocation={d}/state\n\
         SlurmdSpoolDir={d}/spool\n\
         SlurmctldPidFile={d}/slurmctld.pid\n\
         SlurmdPidFile={d}/slurmd.pid\n\
         SlurmctldLogFile={d}/log/slurmctld.log\n\
         SlurmdLogFile={d}/log/slurmd.log\n\
         ProctrackType=proctrack/linuxproc\n\
         TaskPlugin=task/none\n\
         SelectType=select/cons_tres\n\
         SelectTypeParameters=CR_Core\n\
         SchedulerType=sched/backfill\n\
         MpiDefault=none\n\
         ReturnToService=2\n\
         MinJobAge=4\n\
         JobCompType=jobcomp/none\n\
         AccountingStorageType=accounting_storage/none\n\
         JobAcctGatherType=jobacct_gather/none\n\
         SwitchType=switch/none\n\
         NodeName={host} CPUs={cpus} State=UNKNOWN\n\
         PartitionName=debug Nodes={host} Default=YES MaxTime=INFINITE State=UP\n"
    )
}

/// The report JSON without its wall-clock times (`runs[*].seconds`).
fn without_seconds(text: &str, what: &str) -> Result<String, String> {
    let mut v: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("{what}: not JSON: {e}"))?;
    for r in v["runs"].as_array_mut().ok_or(format!("{what}: no runs"))? {
        if let Some(o) = r.as_object_mut() {
            o.remove("seconds");
        }
    }
    Ok(v.to_string())
}

/// The `afsv` binary given as `--bin PATH` (CI passes the one its single release build
/// made), or `None` (no arguments): build it with `cargo build -p afsv --release`.
fn given_binary(args: &[String]) -> Result<Option<PathBuf>, String> {
    match args {
        [] => Ok(None),
        [flag, path] if flag == "--bin" => {
            let bin = PathBuf::from(path);
            std::fs::canonicalize(&bin)
                .map(Some)
                .map_err(|e| format!("slurm-test: {}: {e}", bin.display()))
        }
        _ => Err(format!(
            "slurm-test: unknown arguments {args:?} (only --bin PATH)"
        )),
    }
}

/// `target/release/afsv`, built by `cargo build -p afsv --release`.
fn build_afsv(root: &Path) -> Result<PathBuf, String> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let built = Command::new(cargo)
        .current_dir(root)
        .args(["build", "-q", "-p", "afsv", "--release"])
        .status()
        .map_err(|e| format!("cannot run cargo build: {e}"))?;
    if !built.success() {
        return Err("cargo build -p afsv --release failed".into());
    }
    Ok(root.join("target").join("release").join("afsv"))
}

/// What running the script and the in-process command needs.
struct Env<'a> {
    root: &'a Path,
    conf: &'a Path,
    afsv: &'a Path,
    cpus: usize,
    log: &'a Path,
}

impl Env<'_> {
    /// `scripts/slurm/optimize.sh PROBLEM OPTIONS` on the Slurm, in `run`.
    fn script(&self, problem: &str, options: &str, run: &Path) -> Result<(), String> {
        let status = Command::new(self.root.join("scripts/slurm/optimize.sh"))
            .arg(problem)
            .args(options.split_whitespace())
            .env("SLURM_CONF", self.conf)
            .env("AFSV", self.afsv)
            .env("SHARDS", self.cpus.to_string())
            .env("WORKDIR", run)
            .status()
            .map_err(|e| format!("cannot run the script: {e}"))?;
        if status.success() {
            Ok(())
        } else {
            Err(format!(
                "scripts/slurm/optimize.sh {problem} failed ({status}); logs in {} and {}",
                self.log.display(),
                run.display()
            ))
        }
    }

    /// The report of the Slurm run in `run` against `afsv optimize PROBLEM --json OPTIONS`
    /// in this process, both through `normal` (text, what) first.
    fn compare(
        &self,
        problem: &str,
        options: &str,
        run: &Path,
        normal: &dyn Fn(&str, &str) -> Result<String, String>,
    ) -> Result<(), String> {
        let in_process = Command::new(self.afsv)
            .args(["--quiet", "optimize", problem, "--json"])
            .args(options.split_whitespace())
            .output()
            .map_err(|e| format!("cannot run afsv: {e}"))?;
        let path = run.join("report.json");
        let report =
            std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let ours = normal(&report, &format!("report.json of the Slurm {problem} run"))?;
        let theirs = normal(
            &String::from_utf8_lossy(&in_process.stdout),
            &format!("in-process {problem} run"),
        )?;
        if ours == theirs {
            Ok(())
        } else {
            Err(format!(
                "the Slurm run's report {} differs from the in-process run's",
                path.display()
            ))
        }
    }
}

/// The task; `args` may name the `afsv` binary to run (`--bin PATH`).
pub fn slurm_test(args: &[String], root: &Path) -> Result<(), String> {
    let given = given_binary(args)?;
    let start = Instant::now();
    if let Some(why) = install() {
        println!("slurm-test: skipped: {why}");
        return Ok(());
    }
    let installed = start.elapsed().as_secs_f64();
    let afsv = match given {
        Some(bin) => bin,
        None => build_afsv(root)?,
    };
    let dir: PathBuf = std::env::temp_dir().join(format!("afsv-slurm-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for sub in ["munge", "state", "spool", "log", "run"] {
        std::fs::create_dir_all(dir.join(sub)).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    let io = |e: std::io::Error| format!("{}: {e}", dir.display());
    // The munge key: 1024 random bytes, readable by munge alone; the socket folder must be
    // searchable by everyone.
    let mut key = vec![0u8; 1024];
    std::io::Read::read_exact(
        &mut std::fs::File::open("/dev/urandom").map_err(io)?,
        &mut key,
    )
    .map_err(io)?;
    let munge = dir.join("munge");
    std::fs::write(munge.join("munge.key"), &key).map_err(io)?;
    output(
        Command::new("chmod")
            .arg("0400")
            .arg(munge.join("munge.key")),
    )?;
    output(Command::new("chmod").arg("0755").arg(&dir).arg(&munge))?;
    output(
        Command::new("chown")
            .arg("-R")
            .arg("munge:munge")
            .arg(&munge),
    )?;
    let host = output(Command::new("hostname").arg("-s"))?;
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    let conf = dir.join("slurm.conf");
    std::fs::write(&conf, slurm_conf(&dir, &host, cpus)).map_err(io)?;
    let log = dir.join("log");
    let mut daemons = Daemons(Vec::new());
    let p = |name: &str| munge.join(name).display().to_string();
    daemons.0.push(spawn(
        "munged",
        Command::new("setpriv")
            .args([
                "--reuid=munge",
                "--regid=munge",
                "--init-groups",
                "munged",
                "-F",
            ])
            .arg(format!("--key-file={}", p("munge.key")))
            .arg(format!("--socket={}", p("munge.socket")))
            .arg(format!("--pid-file={}", p("munged.pid")))
            .arg(format!("--log-file={}", p("munged.log")))
            .arg(format!("--seed-file={}", p("munged.seed"))),
        &log.join("munged.out"),
    )?);
    let socket = munge.join("munge.socket");
    wait_for("munged", 20, &mut || socket.exists())?;
    for (name, program) in [("slurmctld", "slurmctld"), ("slurmd", "slurmd")] {
        daemons.0.push(spawn(
            name,
            Command::new(program).arg("-D").arg("-f").arg(&conf),
            &log.join(format!("{name}.out")),
        )?);
    }
    wait_for("the Slurm node (sinfo: idle)", 60, &mut || {
        output(
            Command::new("sinfo")
                .args(["-h", "-N", "-n", &host, "-o", "%T"])
                .env("SLURM_CONF", &conf),
        )
        .is_ok_and(|s| s == "idle")
    })
    .map_err(|e| format!("{e}; logs in {}", log.display()))?;
    let up = start.elapsed().as_secs_f64();
    eprintln!(
        "slurm-test: single-node Slurm up on {host} ({cpus} CPUs) in {up:.1} s; running scripts/slurm/optimize.sh afs, then layout"
    );
    let env = Env {
        root,
        conf: &conf,
        afsv: &afsv,
        cpus,
        log: &log,
    };
    let afs_run = dir.join("run");
    env.script("afs", OPTIONS, &afs_run)?;
    let afs_s = start.elapsed().as_secs_f64() - up;
    let layout_run = dir.join("run-layout");
    env.script("layout", LAYOUT_OPTIONS, &layout_run)?;
    let on_slurm = start.elapsed().as_secs_f64() - up;
    drop(daemons);
    env.compare("afs", OPTIONS, &afs_run, &|t, w| without_seconds(t, w))?;
    env.compare("layout", LAYOUT_OPTIONS, &layout_run, &|t, w| {
        serde_json::from_str::<serde_json::Value>(t)
            .map(|v| v.to_string())
            .map_err(|e| format!("{w}: not JSON: {e}"))
    })?;
    let run = afs_run;
    let batches = std::fs::read_dir(run.join("logs")).map_or(0, |d| d.count()) / cpus.max(1);
    let _ = std::fs::remove_dir_all(&dir);
    println!(
        "slurm-test: passed: the job-array runs (afs: {batches} batches x {cpus} shards, {afs_s:.1} s; layout: {:.1} s) equal the in-process optima byte for byte; install {installed:.1} s, Slurm up {:.1} s, runs {on_slurm:.1} s, total {:.1} s",
        on_slurm - afs_s,
        up - installed,
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
