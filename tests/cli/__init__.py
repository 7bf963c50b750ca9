"""Tests of electrogrowth.cli."""
