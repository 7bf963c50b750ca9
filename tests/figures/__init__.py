"""Tests of electrogrowth.figures."""
