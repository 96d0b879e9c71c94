# Zeta Lab — 简体中文. Ids and variables as in en.ftl.

## 页面

page-skip = 跳到演示
page-demo = 演示
page-share = 分享／嵌入
page-loading = 正在加载求解器…
page-footer = Zeta Lab——本页的每个数字都由 Rust（编译为 WebAssembly）根据解析解计算得出。
page-parameters = 参数
page-readouts = 读数
page-about = 关于本演示
page-plot-in-view = 当前图表
page-presets = 预设
page-reset = 恢复默认值
page-exact-value = 精确值
page-export-group = 导出{ $plot }
page-download = 将{ $plot }下载为 { $format }
page-play = 播放
page-pause = 暂停
page-sound-on = 声音开
page-sound-off = 声音关
page-sound-hint = 聆听 x(t)：音高随位移变化
page-anim-time = 动画时间
page-time-words = 时间 { $t } 秒
page-schematic = 动画示意图
page-dismiss = 关闭通知
page-failed = 出现错误，演示已重新启动：{ $text }
page-no-demo = 没有名为“{ $id }”的演示；显示 { $fallback }。
page-no-wasm = 无法加载求解器（{ $text }）。本页需要 WebAssembly。
page-copy = 复制
page-equation = 方程
page-tour-head = 论文，逐图核对
page-tour-open = 在演示中打开此状态
page-tour-paper = 论文给出
page-tour-app = 本应用计算得
page-tour-confirmed = 一致。
page-tour-differs = 不一致。
page-copied = 已复制
page-copy-manual = 请选中并复制（Ctrl+C）
page-share-title = 分享或嵌入“{ $title }”
page-embed-view = {" "}嵌入视图（无网站页眉）
page-autoplay = {" "}自动播放动画
page-theme = 主题{" "}
page-width = {" "}宽度{" "}
page-height = {" "}高度{" "}
page-sliders-shown = 显示的滑块
page-sliders-locked = 锁定的滑块
page-plots-shown = 显示的图表
page-link = 链接
page-embed-code = 嵌入代码
page-preview = 嵌入演示的预览
page-close = 关闭
page-language = 语言
page-language-nav = 语言
page-demos-nav = 演示
page-no-script = Zeta Lab 需要 JavaScript 和 WebAssembly。
page-catalogue-failed = 无法加载{ $name }语言包（{ $text }）；页面仍以英文显示。
page-provisional = { $value }（暂定）
page-readouts-shown = 显示的读数
page-state-token = 状态令牌
page-theme-auto = 自动
page-theme-light = 浅色
page-theme-dark = 深色
page-theme-projector = 投影（高对比度）
page-share-visitor-language = 访问者的语言
page-share-language = {" "}语言{" "}
page-share-fullscreen = {" "}全屏按钮
page-share-ranges = 滑块的范围和步长（留空则保留声明值）
page-share-col-slider = 滑块
page-share-col-from = 最小值
page-share-col-to = 最大值
page-share-col-step = 步长
page-share-range-from = { $label }：最小值
page-share-range-to = { $label }：最大值
page-share-range-step = { $label }：步长
page-share-predict-task = 预测任务
page-share-none = 无
page-share-predict = 学生预测{" "}
page-share-predict-within = {" "}容差{" "}
page-share-presets = 教师预设（包含在链接中）
page-share-preset-example = 例如：轻阻尼
page-share-preset-add = 添加屏幕上的数值
page-share-preset-format = 格式：名称:键=值,键=值; 下一个名称:…
page-share-preset-default = 预设 { $n }
page-share-preset-name = 名称{" "}
page-share-preset-list = 预设{" "}
page-lecturer-presets = 教师预设
page-full-screen = 全屏
page-exit-full-screen = 退出全屏
page-no-stamp = 此文件不含 Zeta Lab 视图（只有 Zeta Lab 导出的 PNG、SVG 和 CSV 才含有）。
page-token-invalid = 此保存的视图不是 Zeta Lab 状态令牌。
page-token-version = 此保存的视图的格式版本为“{ $version }”，本页无法读取；未做任何更改。
page-token-damaged = 此保存的视图已损坏，无法读取；未做任何更改。
page-token-no-demo = 此保存的视图指向本页没有的演示（“{ $demo }”）；未做任何更改。
page-token-other-version-missing = 此保存的视图来自另一版本的 Zeta Lab：其中没有 { $missing }，已使用默认值。
page-token-other-version-unknown = 此保存的视图来自另一版本的 Zeta Lab：此处不认识 { $unknown }，已忽略。
page-token-other-version-both = 此保存的视图来自另一版本的 Zeta Lab：其中没有 { $missing }，已使用默认值；此处不认识 { $unknown }，已忽略。
page-predict-title = 先预测
page-predict-hint = 在你作出预测之前，图表和“{ $label }”保持隐藏。输入你的预测并按回车键。
page-predict-field = 你对“{ $label }”的预测
page-predict-field-unit = 你对“{ $label }”的预测（{ $unit }）
page-predict-reveal = 揭晓
page-predict-nan = “{ $text }”不是数字。请输入数字，例如 { $example }。
page-predict-undefined = 在这些参数下“{ $label }”没有定义；请修改参数后重试。
page-predict-result-inside = 你预测的是 { $p }；“{ $label }”为 { $v }：{ $how }，在容差 { $tol } 之内。
page-predict-result-outside = 你预测的是 { $p }；“{ $label }”为 { $v }：{ $how }，超出容差 { $tol }。
page-predict-exact = 完全正确
page-predict-high = 偏高 { $d }
page-predict-low = 偏低 { $d }

## 图表

plot-clipped = 已截断：部分数值超出坐标轴范围

## 共用词：坐标轴、阻尼状态

axis-time = 时间 t
axis-displacement = 位移 x
axis-extension = 伸长量 x
axis-force = 力 F
axis-velocity = 速度 v
axis-real-part = 实部 Re s
axis-imaginary-part = 虚部 Im s
regime-undamped = 无阻尼
regime-underdamped = 欠阻尼
regime-critically-damped = 临界阻尼
regime-overdamped = 过阻尼
regime-negatively-damped = 负阻尼
regime-neutral = 中性
regime-divergent = 发散

## 演示
