//! Partitioning BOX1BL (balanced, deterministic) and scattering it over
//! MPI ranks (`mpirun -n 2`, `-n 4 --oversubscribe`).

mod common;
use common::*;

fn partition(np: u32) -> serde_json::Value {
    crashsim_json(&[
        "partition",
        qa_deck("BOX1BL").to_str().unwrap(),
        "--np",
        &np.to_string(),
        "--json",
    ])
}

#[test]
fn box1bl_partition_is_balanced_and_deterministic() {
    for np in [2u32, 4] {
        let a = partition(np);
        let b = partition(np);
        assert_eq!(a, b, "two runs with --np {np} differ");
        let imb = a["imbalance"].as_f64().unwrap();
        assert!(imb <= 0.05, "--np {np}: imbalance {imb} > 5%");
        let ranks = a["per_rank"].as_array().unwrap();
        assert_eq!(ranks.len(), np as usize);
        let elems: u64 = ranks.iter().map(|r| r["elements"].as_u64().unwrap()).sum();
        assert_eq!(elems, 140, "--np {np}: every element on exactly one rank");
        assert!(
            ranks.iter().all(|r| r["elements"].as_u64().unwrap() > 0),
            "--np {np}: an empty rank"
        );
        assert!(
            ranks
                .iter()
                .all(|r| r["shared_nodes"].as_u64().unwrap() > 0),
            "--np {np}: a connected tube must share nodes across ranks"
        );
        let part = a["part"].as_array().unwrap();
        assert_eq!(part.len(), 140);
        assert!(part.iter().all(|p| p.as_u64().unwrap() < np as u64));
    }
}

/// Each rank's report from `crashsim distribute --json` under mpirun.
fn distribute(np: u32) -> Vec<serde_json::Value> {
    let out = mpirun(
        np,
        &["distribute", "--json", qa_deck("BOX1BL").to_str().unwrap()],
    );
    assert!(
        out.status.success(),
        "mpirun -n {np} failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter(|l| l.starts_with('{'))
        .map(|l| serde_json::from_str(l).expect("one JSON object per rank"))
        .collect()
}

fn check_scatter(np: u32) {
    let ranks = distribute(np);
    assert_eq!(ranks.len(), np as usize, "one report per rank");
    for (i, r) in ranks.iter().enumerate() {
        assert_eq!(r["rank"].as_u64(), Some(i as u64));
        assert_eq!(r["nranks"].as_u64(), Some(np as u64));
        assert_eq!(
            r["shared_agree"],
            serde_json::Value::Bool(true),
            "rank {i}: shared-node lists disagree with a neighbour"
        );
        assert!(r["elements"].as_u64().unwrap() > 0);
    }
    // Counts per rank sum to the whole: elements exactly once, nodes at
    // least once (shared ones on several ranks), and the shared nodes account
    // for the difference.
    let total_elems = ranks[0]["total_elements"].as_u64().unwrap();
    let total_nodes = ranks[0]["total_nodes"].as_u64().unwrap();
    assert_eq!(total_elems, 140);
    assert_eq!(total_nodes, 155);
    let sum_elems: u64 = ranks.iter().map(|r| r["elements"].as_u64().unwrap()).sum();
    assert_eq!(sum_elems, total_elems);
    let sum_nodes: u64 = ranks.iter().map(|r| r["nodes"].as_u64().unwrap()).sum();
    let sum_shared: u64 = ranks
        .iter()
        .map(|r| r["shared_nodes"].as_u64().unwrap())
        .sum();
    // Node 155 (the rigid body's main node) belongs to no element: rank 0 holds it.
    assert!(
        sum_nodes >= total_nodes && sum_nodes - sum_shared <= total_nodes,
        "nodes {sum_nodes}, shared {sum_shared}, total {total_nodes}"
    );
    if np == 2 {
        // With two ranks every shared node is on both: each rank counts it once.
        assert_eq!(ranks[0]["shared_nodes"], ranks[1]["shared_nodes"]);
        assert_eq!(
            sum_nodes - ranks[0]["shared_nodes"].as_u64().unwrap(),
            total_nodes
        );
    }
    // Neighbour relation is symmetric.
    for (i, r) in ranks.iter().enumerate() {
        for nb in r["neighbours"].as_array().unwrap() {
            let j = nb.as_u64().unwrap() as usize;
            assert!(
                ranks[j]["neighbours"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .any(|x| x.as_u64() == Some(i as u64)),
                "rank {i} lists {j} but not the reverse"
            );
        }
    }
}

#[test]
fn box1bl_scatters_over_two_ranks() {
    check_scatter(2);
}

#[test]
fn box1bl_scatters_over_four_ranks() {
    check_scatter(4);
}

#[test]
fn distribute_bad_deck_takes_the_job_down_with_exit_2() {
    let out = mpirun(2, &["distribute", "/nonexistent/deck_0000.rad"]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent/deck_0000.rad"));
}
