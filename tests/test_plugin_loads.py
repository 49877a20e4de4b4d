"""Where a C++ node creates pluginlib classes, read from its text when the AST lost the loader's type."""

from __future__ import annotations

from archlog.extract.cpp.clang_ast import blank_comments
from archlog.extract.cpp.plugin_loads import creates_plugin, plugin_load_lines

TEXT = """\
void Host::configure() {
  // loader_.createUniqueInstance(type) is how it is done
  navigators_.push_back(loader_.createUniqueInstance(type));
  auto layer = layer_loader_->createSharedInstance<Layer>(
    name);
  auto printed = "->createInstance(x)";
  plugin_ = createInstance(type);
}
void Other::run() { auto raw = loader.createUnmanagedInstance(type); }
"""


def test_loads_outside_comments_and_strings_within_the_node_code() -> None:
    text = blank_comments(TEXT)
    assert plugin_load_lines(text, None) == [3, 4, 9]
    assert plugin_load_lines(text, [(1, 8)]) == [3, 4]


def test_only_pluginlib_loaders_create_plugins() -> None:
    assert creates_plugin("pluginlib::ClassLoader<nav::Planner>", "createUniqueInstance")
    assert not creates_plugin("pluginlib::ClassLoader<nav::Planner>", "getName")
    assert not creates_plugin("factory::Registry", "createInstance")
