"""A chat-completions server on 127.0.0.1 that misbehaves on purpose, at the byte level, for
the hostile-server tests: each scenario writes its own raw HTTP answer (endless bodies, bombs,
trickles, absurd headers), which a well-behaved framework would not let a test write."""

from __future__ import annotations

import functools
import json
import socket
import socketserver
import threading
import time
import zlib
from typing import Callable

#: a scenario answers one request: (socket file to write to, method, path) -> None
Scenario = Callable[[socket.socket, str, str], None]


def _head(status: str, headers: dict[str, str]) -> bytes:
    lines = [f"HTTP/1.1 {status}"] + [f"{k}: {v}" for k, v in headers.items()]
    return ("\r\n".join(lines) + "\r\n\r\n").encode()


def chat_reply(content: str = '{"ranked_instance_ids": [1]}') -> bytes:
    return json.dumps({"choices": [{"message": {"role": "assistant", "content": content},
                                    "finish_reason": "stop"}],
                       "usage": {"prompt_tokens": 3, "completion_tokens": 2}}).encode()


def send(sock: socket.socket, status: str, body: bytes, **headers: str) -> None:
    sock.sendall(_head(status, {"Content-Type": "application/json", "Content-Length": str(len(body)),
                                "Connection": "close", **headers}) + body)


def normal(sock, method, path):
    if path.endswith("/models"):
        send(sock, "200 OK", b'{"data": []}')
    else:
        send(sock, "200 OK", chat_reply())


def endless_body(sock, method, path):
    """200, chunked, 64 KiB chunks for ever."""
    sock.sendall(_head("200 OK", {"Content-Type": "application/json", "Transfer-Encoding": "chunked"}))
    chunk = b"7" * 65536
    while True:
        sock.sendall(b"%x\r\n%s\r\n" % (len(chunk), chunk))


@functools.cache
def bomb() -> bytes:
    """A gzip body of about 32 KB that inflates to 32 MiB of zeros (made once)."""
    compress = zlib.compressobj(9, zlib.DEFLATED, 31)
    block = bytes(1 << 20)
    return b"".join(compress.compress(block) for _ in range(32)) + compress.flush()


def gzip_bomb(sock, method, path):
    """200 with `bomb()` as a gzip body."""
    send(sock, "200 OK", bomb(), **{"Content-Encoding": "gzip"})


def trickle(sock, method, path):
    """200 with a plausible length, then one byte every 0.2 s (no read ever times out)."""
    sock.sendall(_head("200 OK", {"Content-Type": "application/json", "Content-Length": "100000"}))
    while True:
        sock.sendall(b" ")
        time.sleep(0.2)


def huge_length(sock, method, path):
    """200 announcing a 2 GB body, fed slowly."""
    sock.sendall(_head("200 OK", {"Content-Type": "application/json", "Content-Length": "2000000000"}))
    while True:
        sock.sendall(b"x" * 1024)
        time.sleep(0.1)


def retry_after_9999(sock, method, path):
    send(sock, "503 Service Unavailable", b'{"error": "busy"}', **{"Retry-After": "Fri, 31 Dec 9999 23:59:59 GMT"})


def retry_after_huge(sock, method, path):
    send(sock, "429 Too Many Requests", b'{"error": "slow down"}', **{"Retry-After": "999999"})


def deep_models(sock, method, path):
    """`/v1/models` nested 100,000 deep; chat answers normally."""
    if path.endswith("/models"):
        send(sock, "200 OK", b"[" * 100000 + b"]" * 100000)
    else:
        send(sock, "200 OK", chat_reply())


def deep_reply(sock, method, path):
    send(sock, "200 OK", b'{"choices": ' + b"[" * 100000 + b"]" * 100000 + b"}")


def endless_models(sock, method, path):
    """`/v1/models` streams for ever; chat answers normally."""
    if path.endswith("/models"):
        endless_body(sock, method, path)
    else:
        send(sock, "200 OK", chat_reply())


def lone_surrogates(sock, method, path):
    """A reply whose content holds lone surrogates (valid JSON escapes, invalid text)."""
    send(sock, "200 OK", chat_reply('{"ranked_instance_ids": [1], "abstain": "\\ud800 x \\udfff"}').replace(
        b"\\\\ud800", b"\\ud800").replace(b"\\\\udfff", b"\\udfff"))


SCENARIOS: dict[str, Scenario] = {
    "endless body": endless_body, "gzip bomb": gzip_bomb, "trickle": trickle, "huge length": huge_length,
    "503 retry-after 9999": retry_after_9999, "429 retry-after 999999": retry_after_huge,
    "deep /models": deep_models, "deep reply": deep_reply, "endless /models": endless_models,
    "lone surrogates": lone_surrogates,
}


class HostileServer:
    """`with HostileServer(scenario) as base_url: ...` serves `scenario` for every request."""

    def __init__(self, scenario: Scenario):
        self.scenario = scenario
        self.requests: list[str] = []
        outer = self

        class Handler(socketserver.BaseRequestHandler):
            def handle(self):
                data = b""
                while b"\r\n\r\n" not in data:
                    part = self.request.recv(65536)
                    if not part:
                        return
                    data += part
                head, _, rest = data.partition(b"\r\n\r\n")
                lines = head.decode("latin-1").split("\r\n")
                method, path = lines[0].split(" ")[:2]
                length = next((int(ln.split(":", 1)[1]) for ln in lines[1:]
                               if ln.lower().startswith("content-length:")), 0)
                while len(rest) < length:
                    part = self.request.recv(65536)
                    if not part:
                        break
                    rest += part
                outer.requests.append(path)
                try:
                    outer.scenario(self.request, method, path)
                except OSError:  # the client hung up: what a bounded client does
                    pass

        class Server(socketserver.ThreadingTCPServer):
            daemon_threads = True
            allow_reuse_address = True

        self._server = Server(("127.0.0.1", 0), Handler)
        self.base_url = f"http://127.0.0.1:{self._server.server_address[1]}/v1"

    def __enter__(self) -> str:
        threading.Thread(target=self._server.serve_forever, daemon=True).start()
        return self.base_url

    def __exit__(self, *exc) -> None:
        self._server.shutdown()
        self._server.server_close()
