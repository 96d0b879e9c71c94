# Zeta Lab — português (Brasil). Ids and variables as in en.ftl.

## A página

page-skip = Ir para a demonstração
page-demo = Demonstração
page-share = Compartilhar / Incorporar
page-loading = Carregando o solucionador…
page-footer = Zeta Lab — cada número desta página é calculado em Rust (compilado para WebAssembly) a partir de soluções exatas.
page-parameters = Parâmetros
page-readouts = Resultados
page-about = Sobre esta demonstração
page-plot-in-view = Gráfico em exibição
page-presets = Predefinições
page-reset = Restaurar padrões
page-exact-value = valor exato
page-export-group = Exportar { $plot }
page-download = Baixar { $plot } como { $format }
page-play = Reproduzir
page-pause = Pausar
page-sound-on = Som ligado
page-sound-off = Som desligado
page-sound-hint = Ouvir x(t): a altura do som acompanha o deslocamento
page-anim-time = Tempo da animação
page-time-words = tempo { $t } segundos
page-schematic = Esquema animado
page-dismiss = Fechar aviso
page-failed = Algo deu errado e a demonstração foi reiniciada: { $text }
page-no-demo = Não existe demonstração chamada “{ $id }”; exibindo { $fallback }.
page-no-wasm = Não foi possível carregar o solucionador ({ $text }). Esta página precisa de WebAssembly.
page-copy = Copiar
page-equation = Equação
page-tour-head = O artigo, figura por figura
page-tour-open = Abrir este estado na demonstração
page-tour-paper = O artigo diz
page-tour-app = O aplicativo calcula
page-tour-confirmed = Confirmado.
page-tour-differs = Difere.
page-copied = Copiado
page-copy-manual = Selecione e copie (Ctrl+C)
page-share-title = Compartilhar ou incorporar “{ $title }”
page-embed-view = {" "}Visualização incorporada (sem cabeçalho do site)
page-autoplay = {" "}Iniciar a animação
page-theme = Tema{" "}
page-width = {" "}Largura{" "}
page-height = {" "}Altura{" "}
page-sliders-shown = Controles deslizantes exibidos
page-sliders-locked = Controles deslizantes bloqueados
page-plots-shown = Gráficos exibidos
page-link = Link
page-embed-code = Código de incorporação
page-preview = Prévia da demonstração incorporada
page-close = Fechar
page-language = Idioma
page-language-nav = Idioma
page-demos-nav = Demonstrações
page-no-script = O Zeta Lab precisa de JavaScript e WebAssembly.
page-catalogue-failed = Não foi possível carregar o catálogo { $name } ({ $text }); a página continua em inglês.
page-provisional = { $value } (provisório)
page-readouts-shown = Resultados exibidos
page-state-token = Código de estado
page-theme-auto = automático
page-theme-light = claro
page-theme-dark = escuro
page-theme-projector = projetor (alto contraste)
page-share-visitor-language = idioma do visitante
page-share-language = {" "}Idioma{" "}
page-share-fullscreen = {" "}Botão de tela cheia
page-share-ranges = Faixas e passos dos controles deslizantes (deixe vazio para manter os declarados)
page-share-col-slider = controle
page-share-col-from = de
page-share-col-to = até
page-share-col-step = passo
page-share-range-from = { $label }: mínimo
page-share-range-to = { $label }: máximo
page-share-range-step = { $label }: passo
page-share-predict-task = Tarefa de previsão
page-share-none = nenhuma
page-share-predict = Os alunos preveem{" "}
page-share-predict-within = {" "}com tolerância{" "}
page-share-presets = Predefinições do professor (incluídas no link)
page-share-preset-example = p. ex. Amortecimento leve
page-share-preset-add = Adicionar os valores da tela
page-share-preset-format = Formato: nome:chave=valor,chave=valor; outro nome:…
page-share-preset-default = Predefinição { $n }
page-share-preset-name = Nome{" "}
page-share-preset-list = Predefinições{" "}
page-lecturer-presets = Predefinições do professor
page-full-screen = Tela cheia
page-exit-full-screen = Sair da tela cheia
page-no-stamp = Este arquivo não contém nenhuma visualização do Zeta Lab (só os PNG, SVG e CSV exportados pelo Zeta Lab contêm).
page-token-invalid = Esta visualização salva não é um código de estado do Zeta Lab.
page-token-version = Esta visualização salva tem a versão de formato “{ $version }”, que esta página não consegue ler; nada foi alterado.
page-token-damaged = Esta visualização salva está danificada e não pode ser lida; nada foi alterado.
page-token-no-demo = Esta visualização salva indica uma demonstração que esta página não tem (“{ $demo }”); nada foi alterado.
page-token-other-version-missing = Esta visualização salva vem de outra versão do Zeta Lab: { $n ->
        [one] { $missing } não consta nela e começa no valor padrão.
       *[other] { $missing } não constam nela e começam no valor padrão.
    }
page-token-other-version-unknown = Esta visualização salva vem de outra versão do Zeta Lab: { $m ->
        [one] { $unknown } não é conhecido aqui e foi ignorado.
       *[other] { $unknown } não são conhecidos aqui e foram ignorados.
    }
page-token-other-version-both = Esta visualização salva vem de outra versão do Zeta Lab: { $n ->
        [one] { $missing } não consta nela e começa no valor padrão
       *[other] { $missing } não constam nela e começam no valor padrão
    }; { $m ->
        [one] { $unknown } não é conhecido aqui e foi ignorado.
       *[other] { $unknown } não são conhecidos aqui e foram ignorados.
    }
page-predict-title = Primeiro, preveja
page-predict-hint = Os gráficos e “{ $label }” ficam ocultos até você fazer sua previsão. Digite-a e pressione Enter.
page-predict-field = Sua previsão de “{ $label }”
page-predict-field-unit = Sua previsão de “{ $label }” ({ $unit })
page-predict-reveal = Revelar
page-predict-nan = “{ $text }” não é um número. Digite um número como { $example }.
page-predict-undefined = “{ $label }” não está definido para estes parâmetros; altere-os e tente novamente.
page-predict-result-inside = Você previu { $p }; “{ $label }” vale { $v }: { $how }, dentro da tolerância de { $tol }.
page-predict-result-outside = Você previu { $p }; “{ $label }” vale { $v }: { $how }, fora da tolerância de { $tol }.
page-predict-exact = exatamente certo
page-predict-high = { $d } acima
page-predict-low = { $d } abaixo

## Gráficos

plot-clipped = cortado: alguns valores ficam além dos eixos

## Palavras compartilhadas: eixos, regimes

axis-time = tempo t
axis-displacement = deslocamento x
axis-extension = alongamento x
axis-force = força F
axis-velocity = velocidade v
axis-real-part = parte real Re s
axis-imaginary-part = parte imaginária Im s
regime-undamped = não amortecido
regime-underdamped = subamortecido
regime-critically-damped = criticamente amortecido
regime-overdamped = superamortecido
regime-negatively-damped = amortecimento negativo
regime-neutral = neutro
regime-divergent = divergente

## Demonstrações
