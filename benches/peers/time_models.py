"""Wall-clock time per call of ABA and RNEA on the imported 3-D trees of examples/models/:
vectrix (benches/models.rs's driver, VECTRIX_ICOUNT_MODEL=algo:file:calls) against Pinocchio
C++ (benches/peers/pin_models.cpp on the models its own parsers make of the same files,
written by scripts/pin_model_dump.py) built -O3 -march=native, Pinocchio at its fastest on
this machine, and for the default x86-64 (SSE2) too. Both single-threaded, interleaved, in one
sitting; each figure is (time of N calls - time of 1 call) / N, the median of TIME_ROUNDS
(default three) rounds, and their minimum.

    sh benches/peers/icount_models.sh "aba" # first: builds the x86-64 peer and dumps the models
    python3 benches/peers/time_models.py     # builds the native peer once (about 5 minutes)
"""
import os
import statistics
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
HOME = os.path.expanduser("~")
NATIVE = os.environ.get("PEERS_BIN_MODELS_NATIVE", f"{HOME}/.cache/vectrix_pin_models_native")
X86_64 = os.environ.get("PEERS_BIN_MODELS", f"{HOME}/.cache/vectrix_pin_models_x86-64")
TMP = os.environ.get("TMPDIR", "/tmp")
MODELS = [("arm7.urdf", 400_000), ("quadruped.urdf", 200_000), ("humanoid.xml", 100_000)]
# interleaved rounds per cell (TIME_ROUNDS, default 3): on a shared machine the minimum over more
# rounds is the steadier figure, and both are printed
ROUNDS = int(os.environ.get("TIME_ROUNDS", "3"))


def bench_binary():
    out = subprocess.run(["cargo", "bench", "--bench", "models", "--no-run"], cwd=ROOT,
                         capture_output=True, text=True, check=True).stderr
    return [l.split("(")[1].rstrip(")") for l in out.splitlines() if "Executable" in l][-1]


def build_native():
    if os.access(NATIVE, os.X_OK):
        return
    venv = os.environ.get("PEERS_VENV", f"{HOME}/.venv-peers")
    lib = os.path.join(venv, "lib")
    py = [d for d in os.listdir(lib) if d.startswith("python3")][0]
    prefix = os.path.join(lib, py, "site-packages", "cmeel.prefix")
    subprocess.run(["g++", "-w", "-std=c++17", "-O3", "-march=native", "-DNDEBUG",
                    "-DBOOST_MPL_LIMIT_LIST_SIZE=30", "-DBOOST_MPL_LIMIT_VECTOR_SIZE=30",
                    "-DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS", "-DBOOST_FUSION_INVOKE_MAX_ARITY=12",
                    f"-I{prefix}/include", f"-I{prefix}/include/eigen3",
                    os.path.join(ROOT, "benches/peers/pin_models.cpp"), "-o", NATIVE], check=True)


def seconds(cmd, env=None):
    t = time.perf_counter()
    subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - t


def main():
    build_native()
    vx = bench_binary()
    algos = sys.argv[1:] or ["aba", "rnea"]
    for model, n in MODELS:
        dump = os.path.join(TMP, f"{model}.pin.txt")
        for algo in algos:
            tools = {
                "vectrix": lambda k: seconds([vx], dict(os.environ, VECTRIX_ICOUNT_MODEL=f"{algo}:{model}:{k}")),
                "Pinocchio native": lambda k: seconds([NATIVE, algo, dump, str(k)]),
                "Pinocchio x86-64": lambda k: seconds([X86_64, algo, dump, str(k)]),
            }
            per = {name: [] for name in tools}
            for _ in range(ROUNDS):
                for name, run in tools.items():
                    per[name].append((run(n) - run(1)) / n)
            med = {name: statistics.median(v) for name, v in per.items()}
            low = {name: min(v) for name, v in per.items()}
            cells = " | ".join(f"{name} {med[name] * 1e9:.0f} ns (min {low[name] * 1e9:.0f})" for name in tools)
            print(f"{model} {algo}: {cells} | ratio to native {med['vectrix'] / med['Pinocchio native']:.2f}"
                  f" (of the minima {low['vectrix'] / low['Pinocchio native']:.2f})", flush=True)


if __name__ == "__main__":
    main()
