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
# algorithm at 16 to 256 bits against the exact or a proven higher-precision reference, on new
# random inputs (1000 per algorithm: over 10 000 inputs, about 40 minutes on two cores).
soundness cases="1000" seconds="900":
    SOUNDNESS_SEED=random SOUNDNESS_CASES={{cases}} SOUNDNESS_SECONDS={{seconds}} SOUNDNESS_BITS=16,24,32,64,128,256 cargo test --release --test soundness -- --nocapture --test-threads=2

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

# The Python package (python/): build it into a virtualenv with maturin and run its tests
# (the CLI comparisons need `cargo build --release` first).
python-test venv=(env_var("HOME") + "/.cache/trajverify-venv"):
    python3 -m venv {{venv}}
    {{venv}}/bin/pip install -q maturin pytest numpy scipy mpmath
    cargo build --release
    VIRTUAL_ENV={{venv}} {{venv}}/bin/maturin develop --release -m python/Cargo.toml
    {{venv}}/bin/python -m pytest -q python/tests

# The Python package against scipy in process (after `just python-test`).
python-bench venv=(env_var("HOME") + "/.cache/trajverify-venv"):
    {{venv}}/bin/python scripts/bench_python.py
