"""Chat model providers: the protocol (`base`), the offline rule-based model, OpenAI-compatible
endpoints and the response cache."""
