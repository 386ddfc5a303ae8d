"""Evaluation: query suites (`suite`), synthetic query generation (`generate`), the resumable
runner (`runner`, journal in `journal`), metrics, paired significance and reports."""
