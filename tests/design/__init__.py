"""Tests of electrogrowth.design."""
