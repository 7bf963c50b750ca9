"""Tests of electrogrowth.bifurcation."""
