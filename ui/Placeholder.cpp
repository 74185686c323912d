// Placeholder until the widgets land.
namespace stepdeck::ui {
int placeholder() { return 0; }
} // namespace stepdeck::ui
