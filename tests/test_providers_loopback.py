"""The loopback server itself, spoken to with raw httpx (no client logic in between)."""

import threading
import time

import httpx
import pytest

from iesm_agent.providers import FunctionModel
from loopback import Fault, LoopbackServer

BODY = {"model": "m", "messages": [{"role": "user", "content": "hi"}]}


def echo(messages, options):
    return f"echo: {messages[-1].text()}"


def post(server, body=BODY, timeout=5.0):
    return httpx.post(server.base_url + "/chat/completions", json=body, timeout=timeout)


def test_answers_in_chat_completions_format():
    with LoopbackServer(FunctionModel(echo)) as server:
        reply = post(server).json()
        models = httpx.get(server.base_url + "/models").json()
    assert reply["choices"][0]["message"] == {"role": "assistant", "content": "echo: hi"}
    assert reply["model"] == "m" and set(reply["usage"]) >= {"prompt_tokens", "completion_tokens"}
    assert models["data"][0]["id"] == "loopback"
    assert server.requests[0].status == 200 and server.requests[0].body == BODY


def test_malformed_requests_and_unknown_routes():
    with LoopbackServer(FunctionModel(echo)) as server:
        not_json = httpx.post(server.base_url + "/chat/completions", content=b"{oops")
        no_messages = post(server, {"model": "m"})
        bad_role = post(server, {"messages": [{"role": "robot", "content": "x"}]})
        bad_image = post(server, {"messages": [{"role": "user", "content": [
            {"type": "image_url", "image_url": {"url": "http://example.com/a.png"}}]}]})
        image_not_object = post(server, {"messages": [{"role": "user", "content": [
            {"type": "image_url", "image_url": "data:image/png;base64,AA=="}]}]})
        bad_format = post(server, {**BODY, "response_format": {"type": "json_schema", "json_schema": "x"}})
        wrong_path = httpx.post(server.base_url + "/completions", json=BODY)
    assert [r.status_code for r in (not_json, no_messages, bad_role, bad_image, image_not_object, wrong_path)] == [
        400, 400, 400, 400, 400, 404]
    # a json_schema that is not an object is ignored (served without a schema), not a server crash
    assert bad_format.status_code == 200 and bad_format.json()["choices"][0]["message"]["content"] == "echo: hi"
    assert "data URL" in bad_image.json()["error"]["message"]


def test_failing_model_becomes_http_500():
    def broken(messages, options):
        raise RuntimeError("model exploded")

    with LoopbackServer(FunctionModel(broken)) as server:
        reply = post(server)
    assert reply.status_code == 500 and "model exploded" in reply.json()["error"]["message"]


def test_fault_queue_is_consumed_in_order():
    faults = ["500", Fault.rate_limited(2), "non_json", "no_choices", "no_content",
              Fault.bad_reply("nope"), None]
    with LoopbackServer(FunctionModel(echo), faults=faults) as server:
        replies = [post(server) for _ in range(8)]
    assert [r.status_code for r in replies] == [500, 429, 200, 200, 200, 200, 200, 200]
    assert replies[1].headers["retry-after"] == "2"
    assert replies[2].headers["content-type"] == "text/html"
    assert "choices" not in replies[3].json()
    assert replies[4].json()["choices"][0]["message"]["content"] is None
    assert replies[5].json()["choices"][0]["message"]["content"] == "nope"
    assert replies[7].json()["choices"][0]["message"]["content"] == "echo: hi"
    assert [r.fault.kind if r.fault else None for r in server.requests] == [
        "status", "status", "non_json", "no_choices", "no_content", "bad_reply", None, None]


def test_callable_faults_see_index_and_body():
    calls = []

    def pick(index, body):
        calls.append((index, body["model"]))
        return 503 if index % 2 == 0 else None

    with LoopbackServer(FunctionModel(echo), faults=pick) as server:
        codes = [post(server).status_code for _ in range(4)]
    assert codes == [503, 200, 503, 200] and calls == [(i, "m") for i in range(4)]


def test_reject_response_format_only_when_present():
    with LoopbackServer(FunctionModel(echo), faults=lambda i, b: "reject_response_format") as server:
        structured = post(server, {**BODY, "response_format": {"type": "json_schema",
                                                               "json_schema": {"name": "r", "schema": {}}}})
        plain = post(server)
    assert structured.status_code == 400 and "response_format" in structured.text
    assert plain.status_code == 200


def test_unknown_fault_name():
    with pytest.raises(ValueError, match="unknown fault"):
        Fault.parse("explode")


def test_concurrent_requests_overlap():
    with LoopbackServer(FunctionModel(echo), delay_s=0.2) as server:
        threads = [threading.Thread(target=post, args=(server,)) for _ in range(5)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    assert server.max_in_flight == 5 and all(r.status == 200 for r in server.requests)


def test_close_does_not_wait_for_slow_faults():
    server = LoopbackServer(FunctionModel(echo), faults=[Fault.slow(30)]).start()
    with pytest.raises(httpx.ReadTimeout):
        post(server, timeout=0.2)
    started = time.perf_counter()
    server.close()
    assert time.perf_counter() - started < 2.0
    assert server.base_url.startswith("http://127.0.0.1:")
