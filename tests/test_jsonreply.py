import pytest

from iesm_agent.providers.jsonreply import JsonReplyError, parse_json_reply


def test_plain_object():
    assert parse_json_reply('{"ranked_instance_ids": [3, 1]}') == {"ranked_instance_ids": [3, 1]}


def test_fenced_block_with_prose_around():
    text = 'Sure! Here is the ranking:\n```json\n{"ranked_instance_ids": [7]}\n```\nHope it helps.'
    assert parse_json_reply(text) == {"ranked_instance_ids": [7]}


def test_unlabelled_fence():
    assert parse_json_reply("```\n{\"object\": \"chair\", \"room\": null}\n```") == {
        "object": "chair", "room": None}


def test_prose_before_and_after_without_fence():
    text = 'I think the answer is {"scores": {"obj": 4, "room": 0}} because of the chair.'
    assert parse_json_reply(text) == {"scores": {"obj": 4, "room": 0}}


def test_trailing_commas():
    text = '{"scores": {"obj": 3, "desc": 1,}, "ids": [1, 2, ],}'
    assert parse_json_reply(text) == {"scores": {"obj": 3, "desc": 1}, "ids": [1, 2]}


def test_commas_inside_strings_are_kept():
    assert parse_json_reply('{"hint": "red, }", "x": [1,],}') == {"hint": "red, }", "x": [1]}


def test_python_style_literals_without_eval():
    text = "{'object': 'mug', 'room': None, 'sure': True, 'note': 'it\\'s red'}"
    assert parse_json_reply(text) == {"object": "mug", "room": None, "sure": True, "note": "it's red"}


def test_code_in_single_quotes_is_not_evaluated():
    with pytest.raises(JsonReplyError):
        parse_json_reply("{'a': __import__('os').getcwd()}")


def test_nested_objects_and_braces_in_strings():
    text = 'answer: {"a": {"b": {"c": [1, {"d": "}{"}]}}, "e": "x"} trailing {"f": 1}'
    assert parse_json_reply(text) == {"a": {"b": {"c": [1, {"d": "}{"}]}}, "e": "x"}


def test_think_block_is_ignored():
    text = '<think>maybe {"ranked_instance_ids": [1]}? no.</think>\n{"ranked_instance_ids": [2]}'
    assert parse_json_reply(text) == {"ranked_instance_ids": [2]}


def test_first_unparseable_brace_skipped_for_later_object():
    assert parse_json_reply('set {x} then {"ok": 1}') == {"ok": 1}


@pytest.mark.parametrize("text", [
    "", "   ", "no json here", "[1, 2, 3]", '"just a string"', "{unclosed", '{"a": NaN}',
    "{'never closed: 1}",
])
def test_no_object_raises_value_error(text):
    with pytest.raises(JsonReplyError) as info:
        parse_json_reply(text)
    assert isinstance(info.value, ValueError)


def test_non_string_input_raises():
    with pytest.raises(JsonReplyError):
        parse_json_reply(None)  # type: ignore[arg-type]


def test_many_braces_bounded():
    text = "{" * 5000 + " nothing"
    with pytest.raises(JsonReplyError):
        parse_json_reply(text)
