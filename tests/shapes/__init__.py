"""Tests of electrogrowth.shapes."""
