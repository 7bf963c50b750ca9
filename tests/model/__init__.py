"""Tests of electrogrowth.model."""
