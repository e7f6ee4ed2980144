//! One frame of the editor: input, the panels laid out around the viewport, and the
//! windows and dialogs over them.

use crate::ui::bug_gallery::bug_gallery_window;
use crate::ui::commands::{Command, Selection};
use crate::ui::compare::{compare_view_ui, compare_window, is_compare_image};
use crate::ui::document::confirm::{DiscardAction, discard_modal};
use crate::ui::document::export::ViewportLook;
use crate::ui::document::export_window::export_window;
use crate::ui::document::files;
use crate::ui::panels::inspector::{inspector_ui, take_field_notice};
use crate::ui::panels::menu::{MenuState, menu_ui};
use crate::ui::panels::notices::{Notice, Tone, notices_ui};
use crate::ui::panels::outliner::outliner_ui;
use crate::ui::panels::status_bar::{StatusInfo, StatusMessage, status_bar_ui};
use crate::ui::shortcuts::{help_window, shortcut_commands};
use crate::ui::style::apply_style;
use crate::ui::viewport::convergence_plot::convergence_plot_ui;
use crate::ui::viewport::exchange::ViewportInput;
use crate::ui::viewport::picture::viewport_ui;
use crate::ui::viewport::pixel_inspector::{InspectorView, pixel_inspector_ui};
use crate::ui::viewport::preview_link::PreviewLink;
use egui::{Color32, RichText, ViewportCommand};
use std::path::PathBuf;

use super::EditorApp;

impl EditorApp {
    /// One frame of the whole editor.
    pub fn editor_ui(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        if !self.styled {
            // Fonts change from the next pass: lay nothing out until then.
            apply_style(&ctx);
            self.styled = true;
            ctx.request_repaint();
            return;
        }
        if self.view.preview_enabled && self.view.preview.is_none() {
            self.view.preview = Some(PreviewLink::new(&ctx));
        }
        if let Some(preview) = &mut self.view.preview {
            preview.poll(&ctx, self.view.preview_settings.nan_guard);
        }
        self.view.looking.start(&ctx);
        match self.view.looking.poll(&self.document.scene) {
            Some(Ok(command)) => self.commands.push(command),
            Some(Err(message)) => self.message = Some(StatusMessage::done(message)),
            None => {}
        }
        self.input(&ctx);
        self.panels_ui(ui);
        self.dialogs(&ctx);
        self.fit_imported_mesh();
        self.apply_commands(&ctx);
        let dirty = self.document.is_dirty();
        let now = std::time::Instant::now();
        if let Some(wait) = self.autosave.tick(
            &self.document.scene,
            dirty,
            self.document.path.as_deref(),
            now,
        ) {
            ctx.request_repaint_after(wait);
        }
        let folder = self.document.scene_folder().map(std::path::Path::to_owned);
        if let Some(preview) = &mut self.view.preview {
            preview.sync(
                self.view.looking.shown_scene(&self.document.scene),
                folder.as_deref(),
                &self.view.preview_settings,
                &self.view.isolation,
            );
        }
        self.view.looking.sync_inspections(
            &self.document.scene,
            self.view.preview_settings.switches,
            &self.view.isolation,
        );
        if self
            .view
            .preview
            .as_ref()
            .is_some_and(|p| p.loading().is_some())
        {
            // The reading's progress bar moves without a frame being published.
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
        if self.view.looking.is_busy() {
            // Frames keep coming until the probe answers (it also wakes the window).
            ctx.request_repaint();
        }
        let title = self.title();
        if title != self.title {
            ctx.send_viewport_cmd(ViewportCommand::Title(title.clone()));
            self.title = title;
        }
        if let Some(hook) = &mut self.screenshot {
            let ready = self.view.preview.as_ref().is_some_and(|p| {
                p.shows_full_resolution()
                    && (!self.screenshot_final || p.shown().is_some_and(|s| s.is_final))
            });
            if let Some(outcome) = hook.step(&ctx, ready) {
                if let Err(error) = outcome {
                    eprintln!("raylab: screenshot failed: {error}");
                }
                self.allow_close = true;
                ctx.send_viewport_cmd(ViewportCommand::Close);
            }
        }
    }

    /// Shortcuts, dropped files and the close button.
    pub(super) fn input(&mut self, ctx: &egui::Context) {
        self.commands.extend(shortcut_commands(ctx));
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_owned())
                .filter(|p| !p.as_os_str().is_empty())
                .collect()
        });
        if let Some(path) = dropped.into_iter().next() {
            if files::is_scene_file(&path) {
                self.commands.push(Command::Open(path));
            } else if is_compare_image(&path) {
                self.commands.push(Command::CompareWith(path));
            } else {
                self.error = Some(format!(
                    "{}: drop a .ron scene to open it, or a .png or .ppm picture to compare with",
                    path.display()
                ));
            }
        }
        if ctx.input(|i| !i.raw.hovered_files.is_empty()) {
            drop_hint(ctx);
        }
        if ctx.input(|i| i.viewport().close_requested())
            && !self.allow_close
            && self.document.is_dirty()
        {
            ctx.send_viewport_cmd(ViewportCommand::CancelClose);
            self.tools.pending = Some(DiscardAction::Quit);
        }
    }

    pub(super) fn panels_ui(&mut self, ui: &mut egui::Ui) {
        let mut commands = std::mem::take(&mut self.commands);
        egui::Panel::top("menu").show(ui, |ui| {
            let state = MenuState {
                recent: &self.recent,
                in_app_dialogs: self.tools.file_dialogs.uses_in_app(),
                fit_imported_meshes: self.document.fit_imported_meshes,
                native_dialogs: self.tools.file_dialogs.native_available(),
                can_undo: self.document.can_undo(),
                can_redo: self.document.can_redo(),
                has_selection: matches!(
                    self.document.selection,
                    Selection::Object(_)
                        | Selection::Part(_)
                        | Selection::Several(_)
                        | Selection::Light(_)
                        | Selection::Material(_)
                ),
                has_object_selected: !self.document.selection.node_paths().is_empty(),
                group_selected: self.document.selection.node_path().is_some_and(|path| {
                    crate::scene::tree::object_at(&self.document.scene.objects, &path)
                        .is_some_and(|o| matches!(o.shape, crate::scene::Shape::Group { .. }))
                }),
            };
            menu_ui(ui, &state, &mut commands);
        });
        let mut notices = Vec::new();
        if let Some(error) = &self.error {
            notices.push(Notice {
                tone: Tone::Error,
                text: error,
                dismiss: Command::DismissError,
            });
        }
        if let Some(warning) = &self.warning {
            notices.push(Notice {
                tone: Tone::Warning,
                text: warning,
                dismiss: Command::DismissWarning,
            });
        }
        let below_menu = ui.available_rect_before_wrap().min.y;
        notices_ui(ui.ctx(), below_menu, notices, &mut commands);
        egui::Panel::bottom("status").show(ui, |ui| {
            let file = self.document.file_label();
            let info = StatusInfo {
                file: &file,
                dirty: self.document.is_dirty(),
                objects: self.document.scene.objects.len(),
                lights: self.document.scene.lights.len(),
                frame: self.view.preview.as_ref().and_then(PreviewLink::shown),
                progress: self
                    .view
                    .preview
                    .as_ref()
                    .and_then(PreviewLink::pass_progress),
                loading: self.view.preview.as_ref().and_then(PreviewLink::loading),
                error: self.view.preview.as_ref().and_then(PreviewLink::error),
                autosave_error: self.autosave.error.as_deref(),
                message: self.message.as_ref(),
            };
            status_bar_ui(ui, &info, &mut commands);
        });
        // A small window starts with narrower side panels, and either can be narrowed
        // further, so the viewport keeps room.
        let window_width = ui.available_width();
        egui::Panel::left("outliner")
            .resizable(true)
            .default_size((window_width * 0.2).clamp(140.0, 230.0))
            .size_range(120.0..=420.0)
            .show(ui, |ui| {
                panel_title_ui(ui, "Outliner");
                outliner_ui(
                    ui,
                    &self.document.scene,
                    &self.document.selection,
                    &self.view.isolation,
                    &mut commands,
                );
            });
        egui::Panel::right("inspector")
            .resizable(true)
            .default_size((window_width * 0.3).clamp(220.0, 330.0))
            .size_range(220.0..=560.0)
            .show(ui, |ui| {
                panel_title_ui(ui, "Inspector");
                let meshes = self
                    .view
                    .preview
                    .as_ref()
                    .map(PreviewLink::mesh_facts)
                    .unwrap_or_default();
                inspector_ui(
                    ui,
                    &self.document.scene,
                    &meshes,
                    &self.document.selection,
                    &mut self.view.focus_name,
                    &mut commands,
                );
                // A rename asked for an item without a name field: forget it.
                self.view.focus_name = false;
                // A typed value the field did not take as typed is said, not dropped.
                if let Some(notice) = take_field_notice(ui.ctx()) {
                    self.message = Some(StatusMessage::notice(notice));
                }
            });
        egui::CentralPanel::no_frame().show(ui, |ui| {
            if self.tools.compare.is_showing() {
                compare_view_ui(
                    ui,
                    &mut self.tools.compare,
                    &self.document.scene,
                    &mut commands,
                );
                return;
            }
            let input = ViewportInput {
                scene: &self.document.scene,
                preview: self.view.preview.as_ref(),
                selection: &self.document.selection,
                settings: &self.view.preview_settings,
                isolation: &self.view.isolation,
                view: &self.view.looking.camera,
                ray_paths: &self.view.looking.ray_paths,
                inspected: self.view.looking.inspected,
                inspections: self.view.looking.inspections(),
            };
            let output = viewport_ui(ui, &input, &mut commands);
            self.view.looking.free_size = output.free_size;
            self.view.looking.anchor = output.anchor;
        });
        self.commands = commands;
    }

    pub(super) fn dialogs(&mut self, ctx: &egui::Context) {
        if let Some(answer) = self.autosave.offer_ui(ctx) {
            self.restore(answer);
        }
        help_window(ctx, &mut self.view.show_help);
        let folder = self.document.scene_folder().map(std::path::Path::to_owned);
        export_window(
            ctx,
            &mut self.tools.export,
            &self.document.scene,
            folder.as_deref(),
            ViewportLook {
                settings: &self.view.preview_settings,
                isolation: &self.view.isolation,
            },
            &mut self.commands,
        );
        compare_window(ctx, &mut self.tools.compare, &mut self.commands);
        bug_gallery_window(
            ctx,
            &mut self.tools.bug_gallery,
            &self.document.scene,
            self.document
                .path
                .as_deref()
                .and_then(std::path::Path::parent),
            &mut self.commands,
        );
        self.file_dialog_ui(ctx);
        if let Some(pixel) = self.view.looking.inspected {
            let view = InspectorView {
                pixel,
                inspection: self.view.looking.inspection(),
                current: self.view.looking.inspections_current(
                    &self.document.scene,
                    self.view.preview_settings.switches,
                    &self.view.isolation,
                ),
                ray_paths: &self.view.looking.ray_paths,
                anchor: self.view.looking.anchor,
                compared: self.tools.compare.pixel_values(pixel),
            };
            pixel_inspector_ui(ctx, &view, &mut self.commands);
        }
        if self.view.preview_settings.show_convergence
            && let Some(preview) = &self.view.preview
        {
            convergence_plot_ui(
                ctx,
                preview.convergence(),
                &self.view.preview_settings,
                &mut self.commands,
            );
        }
        if let Some(action) = self.tools.pending.clone()
            && let Some(answer) = discard_modal(ctx, &action)
        {
            self.tools.pending = None;
            self.answer_discard(action, answer, ctx);
        }
    }
}

/// While files are dragged over the window: say what dropping does.
fn drop_hint(ctx: &egui::Context) {
    let painter = ctx.layer_painter(egui::LayerId::new(
        egui::Order::Foreground,
        egui::Id::unique("drop hint"),
    ));
    let rect = ctx.content_rect();
    painter.rect_filled(rect, 0.0, Color32::from_black_alpha(170));
    painter.text(
        rect.center(),
        egui::Align2::CENTER_CENTER,
        "Drop a .ron scene to open it, or a PNG to compare with",
        egui::FontId::proportional(22.0),
        Color32::WHITE,
    );
}

fn panel_title_ui(ui: &mut egui::Ui, title: &str) {
    ui.add_space(6.0);
    ui.label(
        RichText::new(title.to_uppercase())
            .small()
            .strong()
            .color(Color32::from_gray(150)),
    );
    ui.add_space(2.0);
}
