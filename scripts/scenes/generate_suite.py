"""Generates probeproxy's test-level suite with headless Blender.

    blender -b --factory-startup --python scripts/scenes/generate_suite.py -- \
        --out DIR [--levels corridor,l_room,...] [--size 64] [--samples 16] [--large]

Blender exits 0 even when a --python script raises, so every failure is turned into a
message and exit code 1 here; a CTest or CI run then sees it.
"""

import sys
import traceback
from pathlib import Path


def _script_args():
    return sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []


def _run():
    sys.dont_write_bytecode = True  # no __pycache__ in the source tree
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from suite import cli

    cli.main(_script_args())


try:
    _run()
except SystemExit as exc:  # argparse's usage errors and --help
    code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    if exc.code is not None and not isinstance(exc.code, int):
        print(f"generate_suite: {exc.code}", file=sys.stderr)
    sys.stdout.flush()
    sys.exit(code)
except BaseException:
    traceback.print_exc()
    print("generate_suite: FAILED (see the traceback above)", file=sys.stderr)
    sys.stderr.flush()
    sys.exit(1)
