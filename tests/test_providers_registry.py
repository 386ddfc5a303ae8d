import textwrap

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.providers import FunctionModel, Message, get_model, providers, register_provider
from loopback import LoopbackServer
from iesm_agent.providers.openai_compat import OpenAICompatModel
from iesm_agent.providers.registry import _REGISTERED

ASK = [Message(role="user", content="hello")]


@pytest.fixture(autouse=True)
def clean_env(monkeypatch):
    for name in ("OPENAI_API_KEY", "IESM_API_KEY", "IESM_BASE_URL", "MY_KEY"):
        monkeypatch.delenv(name, raising=False)


def test_unknown_prefix_lists_known_ones():
    with pytest.raises(IesmError) as info:
        get_model("nosuch:model")
    message = str(info.value)
    assert "'nosuch'" in message
    for known in ("offline", "openai", "ollama", "openai-compat"):
        assert known in message


@pytest.mark.parametrize("spec", ["", "   ", 42])
def test_bad_spec(spec):
    with pytest.raises(IesmError, match="model spec"):
        get_model(spec)


def test_model_instance_passes_through():
    model = FunctionModel(lambda m, o: "x")
    assert get_model(model) is model


def test_openai_needs_a_key(monkeypatch):
    with pytest.raises(IesmError, match="OPENAI_API_KEY"):
        get_model("openai:gpt-4o-mini")
    monkeypatch.setenv("OPENAI_API_KEY", "sk-abc")
    model = get_model("openai:gpt-4o-mini", timeout=5, max_retries=1, concurrency=3)
    assert isinstance(model, OpenAICompatModel)
    assert model.name == "openai:gpt-4o-mini" and model.endpoint == "https://api.openai.com/v1/chat/completions"
    assert (model.timeout, model.max_retries, model.concurrency) == (5.0, 1, 3)
    assert model.capabilities.vision and model.capabilities.json_schema
    assert "sk-abc" not in repr(model) and "sk-abc" not in str(model.cache_identity())
    assert not get_model("openai:gpt-4o-mini", vision=False).capabilities.vision


def test_openai_with_base_url_key_optional():
    model = get_model("openai:local", base_url="http://127.0.0.1:9/v1/")
    assert model.base_url == "http://127.0.0.1:9/v1" and model.capabilities.vision


def test_api_key_env_must_be_set(monkeypatch):
    with pytest.raises(IesmError, match="MY_KEY"):
        get_model("openai:gpt-4o-mini", api_key_env="MY_KEY")
    with pytest.raises(IesmError, match="MY_KEY"):
        get_model("ollama:llama3.1", api_key_env="MY_KEY")
    monkeypatch.setenv("MY_KEY", "k")
    assert get_model("openai:gpt-4o-mini", api_key_env="MY_KEY").model == "gpt-4o-mini"


def test_ollama_defaults():
    model = get_model("ollama:llama3.1")
    assert model.endpoint == "http://localhost:11434/api/chat"
    assert model.name == "ollama:llama3.1" and not model.capabilities.vision


def test_model_name_required():
    for spec in ("openai", "ollama:", "openai-compat"):
        with pytest.raises(IesmError, match="model name"):
            get_model(spec, base_url="http://x")


def test_openai_compat_base_url_from_argument_or_env(monkeypatch):
    with pytest.raises(IesmError, match="IESM_BASE_URL"):
        get_model("openai-compat:qwen")
    monkeypatch.setenv("IESM_BASE_URL", "http://127.0.0.1:8000/v1")
    assert get_model("openai-compat:qwen").base_url == "http://127.0.0.1:8000/v1"
    assert get_model("openai-compat:qwen", base_url="http://h:1/v1").base_url == "http://h:1/v1"


@pytest.mark.parametrize("env", ["IESM_API_KEY", "OPENAI_API_KEY", None])
def test_openai_compat_sends_key_from_environment(monkeypatch, env):
    if env:
        monkeypatch.setenv(env, "secret-1")
    with LoopbackServer(FunctionModel(lambda m, o: "ok")) as server:
        model = get_model("openai-compat:m", base_url=server.base_url)
        assert model.complete(ASK).text == "ok"
    auth = server.requests[0].headers.get("authorization")
    assert auth == ("Bearer secret-1" if env else None)


def test_bad_option_is_an_iesm_error():
    with pytest.raises(IesmError, match="timeout"):
        get_model("ollama:x", timeout=0)
    with pytest.raises(IesmError, match="bad option"):
        get_model("ollama:x", temprature=0.1)


def test_offline_spec():
    offline = pytest.importorskip("iesm_agent.providers.offline", reason="offline model not written yet")
    if not hasattr(offline, "OfflineModel"):
        pytest.skip("offline model not written yet")
    model = get_model("offline")
    assert model.name == "offline"
    with pytest.raises(IesmError, match="no model name"):
        get_model("offline:big")


def test_runtime_registration():
    try:
        register_provider("echo", lambda name, **opts: FunctionModel(lambda m, o: name, name=f"echo:{name}"))
        model = get_model("echo:abc")
        assert model.name == "echo:abc" and model.complete(ASK).text == "abc"
        assert "echo" in providers()
    finally:
        _REGISTERED.pop("echo", None)
    with pytest.raises(IesmError, match="built-in"):
        register_provider("openai", lambda name, **opts: None)


def test_factory_must_return_a_model():
    try:
        register_provider("broken", lambda name, **opts: "not a model")
        with pytest.raises(IesmError, match="not a Model"):
            get_model("broken:x")
    finally:
        _REGISTERED.pop("broken", None)


def _install_plugin(root, module, body):
    """A real installed distribution (dist-info + module) on `root`, found by importlib.metadata."""
    (root / f"{module}.py").write_text(textwrap.dedent(body))
    info = root / f"{module}-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {module}\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text(
        f"[iesm_agent.providers]\nplug = {module}:make\nopenai = {module}:make\n")


def test_entry_point_plugin(tmp_path, monkeypatch):
    _install_plugin(tmp_path, "iesm_test_plugin_ok", """
        from iesm_agent.providers import FunctionModel

        def make(model_name, **opts):
            reply = f"{model_name} timeout={opts['timeout']} extra={opts.get('flavour')}"
            return FunctionModel(lambda m, o: reply, name=f"plug:{model_name}")
    """)
    monkeypatch.syspath_prepend(str(tmp_path))
    model = get_model("plug:tiny", timeout=9, flavour="mint")
    assert model.name == "plug:tiny"
    assert model.complete(ASK).text == "tiny timeout=9 extra=mint"
    with pytest.raises(IesmError, match="OPENAI_API_KEY"):  # built-ins win over plugins
        get_model("openai:gpt-4o-mini")


def test_broken_plugin_names_the_entry_point(tmp_path, monkeypatch):
    _install_plugin(tmp_path, "iesm_test_plugin_broken", "raise ImportError('missing dependency foo')\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(IesmError, match="iesm_agent.providers:plug.*missing dependency foo"):
        get_model("plug:x")


def test_llamacpp_spec_needs_an_existing_gguf_file(tmp_path):
    with pytest.raises(IesmError, match="give a GGUF file"):
        get_model("llamacpp:")
    with pytest.raises(IesmError, match="no such GGUF model file"):
        get_model(f"llamacpp:{tmp_path / 'missing.gguf'}")
    assert "llamacpp" in providers()


def test_request_timeout_from_the_environment(monkeypatch):
    monkeypatch.setenv("IESM_TIMEOUT", "300")
    assert get_model("openai-compat:m", base_url="http://127.0.0.1:9/v1").timeout == 300.0
    assert get_model("openai-compat:m", base_url="http://127.0.0.1:9/v1", timeout=5).timeout == 5.0
    monkeypatch.setenv("IESM_TIMEOUT", "soon")
    with pytest.raises(IesmError, match="IESM_TIMEOUT: must be a number of seconds"):
        get_model("openai-compat:m", base_url="http://127.0.0.1:9/v1")
