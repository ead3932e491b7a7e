"""What the Python package's tests share: the command line to compare with, and the DEMs."""

import os
import subprocess

import pytest

SAMPLE = os.environ.get("TSK_SAMPLE_DEM", "resources/sample/jacksboro_utm16n.tif")
DATA = os.environ.get("TSK_TEST_DATA", "tests/data")
CLI = os.environ.get("TSK_CLI_BINARY", "build/cli/terrain-sketch")


def run_cli(*arguments):
    """Runs the terrain-sketch program; returns its exit code and standard error."""
    done = subprocess.run([CLI, *map(str, arguments)], capture_output=True, text=True)
    return done.returncode, done.stderr


@pytest.fixture
def cli():
    return run_cli
