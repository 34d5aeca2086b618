"""Shared fixtures: the module under test and the CLI of the same build (CTest sets
LINKWRIGHT_CLI to it and PYTHONPATH to the build's python folder)."""

import os

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("LINKWRIGHT_CLI")
    if not path:
        pytest.fail("LINKWRIGHT_CLI is not set: run these tests through CTest (ctest -R python)")
    return path
