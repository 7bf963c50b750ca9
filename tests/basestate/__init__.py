"""Tests of electrogrowth.basestate."""
