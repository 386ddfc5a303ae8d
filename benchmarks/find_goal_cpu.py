"""Where the CPU of one `find_goal` goes, in-process (no HTTP): the parts of MTEFR with the offline
model, measured with per-thread CPU time around each part, on the queries `bench_server.py` sends
in its bursts (first time in the process, then repeated), and the server's own share
(`MapService.find_goal`, all threads, minus the retrieval alone: the model's calls run on the
server's loop when the encoder holds every row they need, as it does for repeated queries; and with
the model called directly, without `OffLoopModel`, which shows what its job costs).

Also measured: the English parser one sentence at a time (as a query asked alone is read) against
`nlp.pipe` over the same sentences in batches of 40, per pipeline component too, and the burst
path: the queries parsed in batches of 40 as `iesm serve` parses the queries waiting together
(`understanding.parse_queries`), then retrieved; and what embedding a sentence the encoder has not
seen costs (the bench queries' embeddings come back from the on-disk vector store), and the MCP
client's check of a find_goal result against the listed output schema.

Run from the repository root: HF_HUB_OFFLINE=1 .venv/bin/python benchmarks/find_goal_cpu.py
(not part of `make bench`: it reports shares, no target).
"""

from __future__ import annotations

import asyncio
import collections
import functools
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from bench_server import queries  # noqa: E402

from iesm_agent.providers.offline import OfflineModel  # noqa: E402
from iesm_agent.providers.offline import model as offline_model  # noqa: E402
from iesm_agent.providers.offline import spatial, tasks  # noqa: E402
from iesm_agent.retrieval import calls, mtefr, retriever  # noqa: E402
from iesm_agent.retrieval.retriever import Retriever  # noqa: E402
from iesm_agent.server import MapService  # noqa: E402
from iesm_agent.store import MapStore, open_map  # noqa: E402
from iesm_agent.understanding import analyse_query, parse, parse_queries, query  # noqa: E402

#: (label, owner, attribute): the parts timed, each with the thread's CPU clock
PARTS = (("English parser (spaCy)", query, "parse_request"),
         ("query analysis, parser included", retriever, "analyse_query"),
         ("offline model answers", OfflineModel, "answer"),
         ("  its prompt reading (read_prompt)", offline_model, "read_prompt"),
         ("  its ranking experts (tasks.rank)", tasks, "rank"),
         ("    the query's candidate matrix (gate, experts)", tasks, "_candidate_matrix"),
         ("  its spatial expert (spatial.rank)", spatial, "rank"),
         ("  the spatial expert's scene read", spatial, "_read_scene"),
         ("spatial reading for the experts asked", mtefr, "parse_query"),
         ("prompt rendering (Jinja)", calls.Session, "render"),
         ("prompt hashes for the trace", calls.PromptHasher, "__call__"),
         ("expert replies read", calls.Session, "ranking"),
         ("gate reply read", mtefr, "_gate_weights"),
         ("fusion", mtefr, "fuse"),
         ("result assembled", Retriever, "_result"))


def timed_parts() -> tuple[collections.Counter, list]:
    """Wrap each of `PARTS` with a CPU-time counter: the counter (seconds per label) and the
    (owner, name, original) to put back."""
    spent: collections.Counter = collections.Counter()
    originals = [(owner, name, getattr(owner, name)) for _, owner, name in PARTS]
    for label, owner, name in PARTS:
        fn = getattr(owner, name)

        @functools.wraps(fn)
        def timed(*args, _fn=fn, _label=label, **kwargs):
            t0 = time.thread_time()
            try:
                return _fn(*args, **kwargs)
            finally:
                spent[_label] += time.thread_time() - t0
        setattr(owner, name, timed)
    return spent, originals


async def retrieval_alone(store, asked: list[str]) -> tuple[float, float, collections.Counter]:
    """CPU ms per query of `Retriever.aask` in one thread (model inline): first time, repeated;
    the parts' ms per query (first time)."""
    r = Retriever(store, provider="offline", method="mtefr")
    await r.aask("a cosy blue wooden seat for reading near the window in the living room")  # loads everything
    spent, originals = timed_parts()
    t0 = time.process_time()
    for q in asked:
        await r.aask(q)
    first = (time.process_time() - t0) * 1000 / len(asked)
    parts = collections.Counter({k: v * 1000 / len(asked) for k, v in spent.items()})
    for owner, name, fn in originals:
        setattr(owner, name, fn)
    t0 = time.process_time()
    for q in asked:
        await r.aask(q)
    return first, (time.process_time() - t0) * 1000 / len(asked), parts


async def served(asked: list[str], rounds: int = 3, inline: bool = False) -> float:
    """CPU ms per repeated query of `MapService.find_goal` (all threads), median of rounds;
    `inline`: the model called directly instead of through `OffLoopModel` (what its job costs)."""
    service = MapService.open(["apartment"])
    await service.warm_up()
    if inline:
        retriever = service.retriever(None, "mtefr", None)
        retriever.model = retriever.model.inner
    for q in asked:
        await service.find_goal(q)
    per_round = []
    for _ in range(rounds):
        t0 = time.process_time()
        for q in asked:
            await service.find_goal(q)
        per_round.append((time.process_time() - t0) * 1000 / len(asked))
    await service.aclose()
    return statistics.median(per_round)


async def burst_path(store, asked: list[str]) -> tuple[float, float]:
    """CPU ms per query of the burst path in one thread: `parse_queries` over batches of 40 of
    `asked` (none parsed before), then `Retriever.aask` of each (its parse memoised)."""
    r = Retriever(store, provider="offline", method="mtefr")
    await r.aask("a cosy blue wooden seat for reading near the window in the living room")
    analyse_query.cache_clear()
    parse.parse_request.cache_clear()
    t0 = time.process_time()
    for i in range(0, len(asked), 40):
        parse_queries(asked[i:i + 40])
    parsed = (time.process_time() - t0) * 1000 / len(asked)
    t0 = time.process_time()
    for q in asked:
        await r.aask(q)
    return parsed, (time.process_time() - t0) * 1000 / len(asked)


def parser_batches(texts: list[str]) -> tuple[float, float, dict[str, tuple[float, float]]]:
    """CPU ms per sentence of the parser one at a time and in `nlp.pipe` batches of 40, and per
    component (name -> (one at a time, batched))."""
    nlp = parse._pipeline()
    t0 = time.process_time()
    for text in texts:
        nlp(text)
    one = (time.process_time() - t0) * 1000 / len(texts)
    t0 = time.process_time()
    list(nlp.pipe(texts, batch_size=40))
    batched = (time.process_time() - t0) * 1000 / len(texts)
    alone = collections.Counter()
    for text in texts:
        doc = nlp.make_doc(text)
        for name, component in nlp.pipeline:
            t0 = time.process_time()
            doc = component(doc)
            alone[name] += time.process_time() - t0
    together = {}
    docs = [nlp.make_doc(text) for text in texts]
    for name, component in nlp.pipeline:
        t0 = time.process_time()
        docs = list(component.pipe(docs, batch_size=40))
        together[name] = time.process_time() - t0
    per_component = {name: (alone[name] * 1000 / len(texts), together[name] * 1000 / len(texts))
                     for name in nlp.pipe_names}
    return one, batched, per_component


async def result_checks(asked: list[str]) -> tuple[float, float]:
    """CPU us per `find_goal` result of the MCP SDK client's check against the listed output schema
    (`jsonschema`, as `ClientSession` validates structured content), with the schema listed now
    (`results.output_schema`) and with pydantic's own (`FindGoalResult.model_json_schema()`)."""
    from jsonschema.validators import validator_for
    from referencing import Registry

    from iesm_agent.server.results import FindGoalResult, output_schema

    service = MapService.open(["apartment"])
    results = [await service.find_goal(q) for q in asked]
    await service.aclose()
    out = []
    for schema in (output_schema(FindGoalResult), FindGoalResult.model_json_schema()):
        validator = validator_for(schema)(schema, registry=Registry())  # as the SDK's client builds it
        t0 = time.process_time()
        for _ in range(5):
            for result in results:
                list(validator.iter_errors(result))
        out.append((time.process_time() - t0) * 1e6 / (5 * len(results)))
    return out[0], out[1]


def new_sentence_embedding(texts: list[str]) -> tuple[float, float] | None:
    """(CPU ms, wall ms) per sentence the encoder's backend takes for a sentence it has not seen
    (one at a time, as a new query is embedded; the backend directly, so nothing is stored), or
    None without an encoder. The bench queries' own embeddings are read back from the on-disk
    vector store once any run has embedded them, so the figures above leave this out."""
    from iesm_agent.embeddings import get_encoder

    encoder = get_encoder()
    if encoder is None:
        return None
    encoder.backend.encode_batch(texts[:1])
    t0, w0 = time.process_time(), time.perf_counter()
    for text in texts:
        encoder.backend.encode_batch([text])
    return (time.process_time() - t0) * 1000 / len(texts), (time.perf_counter() - w0) * 1000 / len(texts)


def main() -> None:
    pool = queries()
    asked = pool[40:160]  # bench_server's burst queries
    first, again, parts = asyncio.run(retrieval_alone(MapStore(open_map("apartment")), asked))
    repeated = asyncio.run(served(asked))
    repeated_inline = asyncio.run(served(asked, inline=True))
    one, batched, per_component = parser_batches([parse.normalise(q) for q in pool])
    parsed, retrieved = asyncio.run(burst_path(MapStore(open_map("apartment")), asked))
    print(f"{len(asked)} queries (bench_server's bursts), CPU ms per query, one thread, no HTTP:")
    print(f"  retrieval (Retriever.aask, model inline): first time {first:.2f}, repeated {again:.2f}")
    for label, ms in parts.most_common():
        print(f"    {label:<36} {ms:6.2f}")
    print(f"  MapService.find_goal, repeated queries (the model's calls on the server's loop: every row "
          f"held), all threads: {repeated:.2f} (server's own share over the retrieval: {repeated - again:+.2f}); "
          f"with the model called directly, no OffLoopModel: {repeated_inline:.2f}")
    print(f"  burst path: parse_queries in batches of 40 {parsed:.2f}, then retrieval {retrieved:.2f}")
    print(f"  English parser: one sentence at a time {one:.2f} ms, nlp.pipe in batches of 40 {batched:.2f} ms "
          f"({len(pool)} suite queries); per component, alone / batched:")
    for name, (alone_ms, batch_ms) in per_component.items():
        print(f"    {name:<36} {alone_ms:6.3f} / {batch_ms:6.3f}")
    listed, pydantic_schema = asyncio.run(result_checks(asked[:40]))
    print(f"  the MCP client's check of a find_goal result against its output schema: {listed:.0f} us "
          f"(pydantic's own schema: {pydantic_schema:.0f} us)")
    embedded = new_sentence_embedding(asked[:40])
    if embedded is not None:
        print(f"  a sentence the encoder has not seen (a new query's embedding, not in the figures above): "
              f"{embedded[0]:.2f} ms of CPU, {embedded[1]:.2f} ms wall")


if __name__ == "__main__":
    main()
