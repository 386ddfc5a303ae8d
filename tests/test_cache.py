import os
import sqlite3
import warnings

import diskcache
import pytest

from iesm_agent.errors import ProviderError
from iesm_agent.providers import CachedModel, ChatOptions, FunctionModel, Message, get_model
from iesm_agent.providers.cache import CacheWarning, cache_key, default_cache_dir
from loopback import LoopbackServer

ASK = [Message(role="user", content="the red chair")]


def counting(reply="chair #3"):
    return FunctionModel(lambda messages, options: reply, name="fn")


async def test_second_identical_request_is_a_hit(tmp_path):
    inner = counting()
    model = CachedModel(inner, tmp_path / "c")
    first = await model.acomplete(ASK)
    second = await model.acomplete(ASK)
    assert second.text == first.text == "chair #3"
    assert (first.cached, second.cached) == (False, True)
    assert (model.hits, model.misses, inner.calls) == (1, 1, 1)
    assert second.latency_ms >= 0 and second.model == first.model


async def test_options_messages_and_identity_are_part_of_the_key(tmp_path):
    inner = counting()
    model = CachedModel(inner, tmp_path)
    await model.acomplete(ASK)
    await model.acomplete(ASK, ChatOptions(temperature=0.5))
    await model.acomplete([Message(role="user", content="the blue chair")])
    other = CachedModel(FunctionModel(lambda m, o: "other", name="fn2"), tmp_path)
    assert (await other.acomplete(ASK)).text == "other"
    assert inner.calls == 3 and model.hits == 0
    assert cache_key(inner, ASK, ChatOptions()) == cache_key(counting(), ASK, ChatOptions())
    assert cache_key(inner, ASK, ChatOptions()) != cache_key(inner, ASK, ChatOptions(seed=1))


async def test_entries_persist_across_instances(tmp_path):
    await CachedModel(counting(), tmp_path).acomplete(ASK)
    again = CachedModel(counting(), tmp_path)
    out = await again.acomplete(ASK)
    assert out.cached and again.hits == 1


async def test_errors_and_empty_replies_are_not_cached(tmp_path):
    state = {"n": 0}

    def flaky(messages, options):
        state["n"] += 1
        if state["n"] == 1:
            raise ProviderError("boom", "test", retryable=True)
        return "" if state["n"] == 2 else "ok"

    model = CachedModel(FunctionModel(flaky), tmp_path)
    with pytest.raises(ProviderError):
        await model.acomplete(ASK)
    assert (await model.acomplete(ASK)).text == ""
    assert (await model.acomplete(ASK)).text == "ok"
    assert (await model.acomplete(ASK)).cached
    assert state["n"] == 3 and model.hits == 1


async def test_values_are_stored_as_text_not_pickles(tmp_path):
    await CachedModel(counting(), tmp_path).acomplete(ASK)
    with sqlite3.connect(tmp_path / "cache.db") as db:
        rows = db.execute("SELECT raw, mode, typeof(key), typeof(value) FROM Cache").fetchall()
    assert rows == [(1, diskcache.core.MODE_RAW, "text", "text")]


class _Planted:
    def __init__(self, marker):
        self.marker = marker

    def __reduce__(self):  # unpickling this would create the marker directory
        return (os.mkdir, (self.marker,))


async def test_pickled_entry_is_never_unpickled(tmp_path):
    inner = counting()
    key = cache_key(inner, ASK, ChatOptions())
    marker = tmp_path / "pwned"
    with diskcache.Cache(str(tmp_path / "c")) as foreign:
        foreign.set(key, _Planted(str(marker)))
        foreign.get(key)  # control: a plain diskcache reader does run the planted callable
    assert marker.exists()
    marker.rmdir()
    model = CachedModel(inner, tmp_path / "c")
    out = await model.acomplete(ASK)
    assert out.text == "chair #3" and not out.cached and inner.calls == 1
    assert not marker.exists()
    assert (await model.acomplete(ASK)).cached  # the foreign entry was overwritten


def _assert_degrades(model, inner):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        texts = [model.complete(ASK).text for _ in range(2)]
    assert texts == ["chair #3"] * 2 and inner.calls == 2
    assert [w.category for w in caught] == [CacheWarning]
    assert str(model.cache_dir) in str(caught[0].message)
    assert model.disabled_reason and model.hits == 0 and model.misses == 2


def test_file_where_the_directory_should_be(tmp_path):
    target = tmp_path / "cache"
    target.write_text("not a directory")
    inner = counting()
    _assert_degrades(CachedModel(inner, target), inner)


def test_garbage_database_file(tmp_path):
    (tmp_path / "cache.db").write_bytes(os.urandom(4096))
    inner = counting()
    _assert_degrades(CachedModel(inner, tmp_path), inner)


def test_permission_denied(tmp_path):
    if os.geteuid() == 0:  # root ignores modes; /sys refuses mkdir even to root (EPERM)
        target = "/sys/iesm-agent-test-cache"
    else:
        locked = tmp_path / "locked"
        locked.mkdir(mode=0o500)
        target = locked / "cache"
    try:
        os.makedirs(target)
    except PermissionError:
        pass
    else:
        pytest.skip("this file system lets us create the directory")
    inner = counting()
    _assert_degrades(CachedModel(inner, target), inner)


def test_default_dir_from_environment(tmp_path, monkeypatch):
    monkeypatch.setenv("IESM_CACHE_DIR", str(tmp_path / "env-cache"))
    assert default_cache_dir() == tmp_path / "env-cache"
    model = get_model(counting(), cache=True)
    assert isinstance(model, CachedModel) and model.cache_dir == tmp_path / "env-cache"
    model.complete(ASK)
    assert (tmp_path / "env-cache" / "cache.db").is_file()
    monkeypatch.delenv("IESM_CACHE_DIR")
    assert default_cache_dir().name == "iesm-agent"


def test_get_model_cache_switch(tmp_path):
    inner = counting()
    assert get_model(inner, cache=None) is inner and get_model(inner, cache=False) is inner
    wrapped = get_model(inner, cache=tmp_path)
    assert isinstance(wrapped, CachedModel) and wrapped.cache_dir == tmp_path
    assert get_model(wrapped, cache=True) is wrapped
    assert wrapped.name == "fn" and wrapped.cache_identity() == inner.cache_identity()


def test_http_model_behind_the_cache(tmp_path):
    with LoopbackServer(counting("from server")) as server:
        model = get_model("openai-compat:m", base_url=server.base_url, cache=tmp_path)
        first, second = model.complete(ASK), model.complete(ASK)
    assert first.text == second.text == "from server" and second.cached
    assert server.request_count == 1 and (model.hits, model.misses) == (1, 1)
