# trajverify tasks. Install just with `cargo install just`; every recipe is a plain cargo
# command, so the README's commands work without it.

export GMP_MPFR_SYS_CACHE := env_var_or_default("GMP_MPFR_SYS_CACHE", env_var("HOME") + "/.cache/gmp-mpfr-sys")

# Check every claim; write reports/ (ledger, Markdown, SVG figures).
verify:
    cargo run --release -- verify

# The test suite (unit, property, snapshot and command-line tests).
test:
    cargo test --release

# The fuzz test for a long run: thousands of mutated inputs of every `run` algorithm, each
# under the 2 GiB memory bound, asserting exit 0 with finite JSON or a one-line exit 2.
fuzz cases="3000" seconds="3600":
    FUZZ_SEED=random FUZZ_CASES={{cases}} FUZZ_SECONDS={{seconds}} cargo test --release --test fuzz -- --nocapture

# The differential soundness test for a long run: every printed digit of every `run`
# algorithm against the exact or 4x-precision reference, on new random inputs.
soundness cases="200" seconds="600":
    SOUNDNESS_SEED=random SOUNDNESS_CASES={{cases}} SOUNDNESS_SECONDS={{seconds}} cargo test --release --test soundness -- --nocapture

# Criterion benches (results under target/criterion).
bench:
    cargo bench

# The performance figures of the README and docs/benchmarks.md, from one bench run.
bench-report:
    cargo build --release
    cargo bench --bench scalar
    cargo bench --bench ph -- ph_c4_segment
    cargo bench --bench param -- marin_objective_exact
    python3 scripts/bench_report.py

# Regenerate the reports into a scratch directory and show any difference from reports/.
report:
    out=$(mktemp -d) && cargo run --release -- verify --out "$out" && diff -r reports "$out" && echo "reports/ is current"

# Review changed claim snapshots (needs `cargo install cargo-insta`), or accept them all.
snapshots:
    INSTA_UPDATE=always cargo test --release --test claims_snapshot
    git diff --stat snapshots/
