"""Outputs of runs: results (series and summaries), plots, JSON conversion."""
