# Zeta Lab — español. Ids and variables as in en.ftl.

## La página

page-skip = Ir a la demostración
page-demo = Demostración
page-share = Compartir / Insertar
page-loading = Cargando el resolvedor…
page-footer = Zeta Lab — cada número de esta página se calcula en Rust (compilado a WebAssembly) con soluciones analíticas.
page-parameters = Parámetros
page-readouts = Resultados
page-about = Acerca de esta demostración
page-plot-in-view = Gráfica a la vista
page-presets = Ajustes predefinidos
page-reset = Restablecer valores
page-exact-value = valor exacto
page-export-group = Exportar { $plot }
page-download = Descargar { $plot } como { $format }
page-play = Reproducir
page-pause = Pausa
page-sound-on = Sonido sí
page-sound-off = Sonido no
page-sound-hint = Escuchar x(t): el tono sigue al desplazamiento
page-anim-time = Tiempo de la animación
page-time-words = tiempo { $t } segundos
page-schematic = Esquema animado
page-dismiss = Cerrar aviso
page-failed = Algo salió mal y la demostración se reinició: { $text }
page-no-demo = No hay ninguna demostración llamada «{ $id }»; se muestra { $fallback }.
page-no-wasm = No se pudo cargar el resolvedor ({ $text }). Esta página necesita WebAssembly.
page-module-failed = No se pudo cargar esta parte de la página ({ $text }). Compruebe la conexión e inténtelo de nuevo.
page-copy = Copiar
page-equation = Ecuación
page-tour-head = El artículo, figura por figura
page-tour-open = Abrir este estado en la demostración
page-tour-paper = El artículo dice
page-tour-app = La aplicación calcula
page-tour-confirmed = Confirmado.
page-tour-differs = Difiere.
page-tour-pending = Comprobando…
page-copied = Copiado
page-copy-manual = Seleccione y copie (Ctrl+C)
page-share-title = Compartir o insertar «{ $title }»
page-embed-view = {" "}Vista insertada (sin cabecera)
page-autoplay = {" "}Iniciar la animación
page-theme = Tema{" "}
page-width = {" "}Ancho{" "}
page-height = {" "}Alto{" "}
page-sliders-shown = Deslizadores visibles
page-sliders-locked = Deslizadores bloqueados
page-plots-shown = Gráficas visibles
page-link = Enlace
page-embed-code = Código para insertar
page-preview = Vista previa de la demostración insertada
page-close = Cerrar
page-language = Idioma
page-language-nav = Idioma
page-demos-nav = Demostraciones
page-no-script = Zeta Lab necesita JavaScript y WebAssembly.
page-catalogue-failed = No se pudo cargar el catálogo de { $name } ({ $text }); la página se muestra en inglés.
page-provisional = { $value } (provisional)
page-study-progress = Calculando el resultado completo
page-readouts-shown = Resultados visibles
page-state-token = Código de estado
page-theme-auto = automático
page-theme-light = claro
page-theme-dark = oscuro
page-theme-projector = proyector (alto contraste)
page-share-visitor-language = idioma del visitante
page-share-language = {" "}Idioma{" "}
page-share-fullscreen = {" "}Botón de pantalla completa
page-share-ranges = Rangos y pasos de los deslizadores (vacío = los declarados)
page-share-col-slider = deslizador
page-share-col-from = desde
page-share-col-to = hasta
page-share-col-step = paso
page-share-range-from = { $label }: mínimo
page-share-range-to = { $label }: máximo
page-share-range-step = { $label }: paso
page-share-predict-task = Tarea de predicción
page-share-none = ninguna
page-share-predict = Los estudiantes predicen{" "}
page-share-predict-within = {" "}con tolerancia{" "}
page-share-presets = Ajustes del docente (incluidos en el enlace)
page-share-preset-example = p. ej. Amortiguamiento ligero
page-share-preset-add = Añadir los valores en pantalla
page-share-preset-format = Formato: nombre:clave=valor,clave=valor; otro nombre:…
page-share-preset-default = Ajuste { $n }
page-share-preset-name = Nombre{" "}
page-share-preset-list = Ajustes{" "}
page-lecturer-presets = Ajustes del docente
page-full-screen = Pantalla completa
page-exit-full-screen = Salir de pantalla completa
page-no-stamp = Este archivo no contiene ninguna vista de Zeta Lab (solo la llevan los PNG, SVG y CSV exportados por Zeta Lab).
page-token-invalid = Esta vista guardada no es un código de estado de Zeta Lab.
page-token-version = Esta vista guardada tiene la versión de formato «{ $version }», que esta página no puede leer; no se cambió nada.
page-token-damaged = Esta vista guardada está dañada y no se puede leer; no se cambió nada.
page-token-no-demo = Esta vista guardada nombra una demostración que esta página no tiene («{ $demo }»); no se cambió nada.
page-token-other-version-missing = Esta vista guardada procede de otra versión de Zeta Lab: { $n ->
        [one] { $missing } no figura en ella y toma el valor por defecto.
       *[other] { $missing } no figuran en ella y toman el valor por defecto.
    }
page-token-other-version-unknown = Esta vista guardada procede de otra versión de Zeta Lab: { $m ->
        [one] { $unknown } no se conoce aquí y se ignoró.
       *[other] { $unknown } no se conocen aquí y se ignoraron.
    }
page-token-other-version-both = Esta vista guardada procede de otra versión de Zeta Lab: { $n ->
        [one] { $missing } no figura en ella y toma el valor por defecto
       *[other] { $missing } no figuran en ella y toman el valor por defecto
    }; { $m ->
        [one] { $unknown } no se conoce aquí y se ignoró.
       *[other] { $unknown } no se conocen aquí y se ignoraron.
    }
page-predict-title = Primero, prediga
page-predict-hint = Las gráficas y «{ $label }» quedan ocultas hasta que haga su predicción. Escríbala y pulse Intro.
page-predict-field = Su predicción de «{ $label }»
page-predict-field-unit = Su predicción de «{ $label }» ({ $unit })
page-predict-reveal = Mostrar
page-predict-nan = «{ $text }» no es un número. Escriba un número como { $example }.
page-predict-undefined = «{ $label }» no está definido con estos parámetros; cámbielos y vuelva a intentarlo.
page-predict-result-inside = Predijo { $p }; «{ $label }» vale { $v }: { $how }, dentro de la tolerancia { $tol }.
page-predict-result-outside = Predijo { $p }; «{ $label }» vale { $v }: { $how }, fuera de la tolerancia { $tol }.
page-predict-exact = exacto
page-predict-high = { $d } por encima
page-predict-low = { $d } por debajo

## Gráficas

plot-clipped = recortado: algunos valores quedan fuera de los ejes

## Avisos (un valor de parámetro que no se pudo usar)

notice-value = { $problem ->
        [toggle] { $label } ({ $key }): «{ $value }» no es sí ni no; se usa el valor predeterminado.
        [option] { $label } ({ $key }): «{ $value }» no es ninguna de { $options }; se usa el valor predeterminado.
        [number] { $label } ({ $key }): «{ $value }» no es un número; se usa el valor predeterminado { $default }.
        [range-empty] { $label } ({ $key }): el intervalo «{ $value }» queda vacío dentro de { $min } … { $max }; se mantiene el intervalo completo.
        [range-not-two-numbers] { $label } ({ $key }): el intervalo «{ $value }» no son dos números «mín,máx»; se mantiene el intervalo completo.
        [step] { $label } ({ $key }): el paso «{ $value }» no es un número entre 0 y { $span }; se mantiene { $step }.
       *[range] { $label } ({ $key }) = { $value } está fuera de { $min } … { $max }{ $unit }; se usa { $used }.
    }

## Archivos exportados

export-csv-heading = Zeta Lab, demostración { $demo }: { $title }
export-series = serie { $n }

## Palabras compartidas: ejes, regímenes

axis-time = tiempo t
axis-displacement = desplazamiento x
axis-extension = extensión x
axis-force = fuerza F
axis-velocity = velocidad v
axis-real-part = parte real Re s
axis-imaginary-part = parte imaginaria Im s
regime-undamped = no amortiguado
regime-underdamped = subamortiguado
regime-critically-damped = amortiguamiento crítico
regime-overdamped = sobreamortiguado
regime-negatively-damped = amortiguamiento negativo
regime-neutral = neutro
regime-divergent = divergente

## Demostraciones

### regimes

regimes-envelope = envolvente ±A·e^(−ζωₙt)
regimes-series-response = x(t), { $regime }
regimes-describe-settles = { $regime }: { $swings ->
        [0] no pasa por el equilibrio antes de establecerse
        [one] pasa por el equilibrio una vez antes de establecerse
       *[other] pasa por el equilibrio { $swings } veces antes de establecerse
    }, queda dentro del 5 % del reposo tras { $time }, rebote máximo { $rebound }.
regimes-describe-unsettled = { $regime }: { $swings ->
        [0] no pasa por el equilibrio antes de establecerse
        [one] pasa por el equilibrio una vez antes de establecerse
       *[other] pasa por el equilibrio { $swings } veces antes de establecerse
    }, no se establece, rebote máximo { $rebound }.
regimes-describe-undamped = no amortiguado: oscila indefinidamente con amplitud { $amplitude } a { $frequency }.
regimes-describe-growing = amortiguamiento negativo: la respuesta crece sin límite, un factor e cada { $time }.
regimes-describe-at-rest = { $regime }: parte del reposo en el equilibrio.
regimes-poles = Polos en { $re1 } { $sign1 } { $im1 }i y { $re2 } { $sign2 } { $im2 }i 1/s, en el semiplano { $side ->
        [right] derecho (inestable)
       *[left] izquierdo (estable)
    }.
regimes-schematic = Masa sobre resorte y amortiguador en t = { $time }: desplazada { $displacement } del reposo.

## Esquemas

schematic-title = Esquema
schematic-circuit = Circuito
### rlc

rlc-axis-current = corriente i
rlc-axis-voltage = tensión del condensador v_C
rlc-envelope = envolvente
rlc-series-critical = R crítica = { $resistance }
rlc-schematic = Circuito RLC serie en t = { $time }: corriente { $current }, condensador a { $voltage }.
rlc-describe-current = { $regime ->
        [undamped] R = { $resistance }, no amortiguado (un circuito LC sin pérdidas): la corriente oscila indefinidamente a ω₀ = { $frequency }, entre ±{ $bound } (toda la energía pasa a la bobina y vuelve cada medio periodo).
        [underdamped] R = { $resistance }, por debajo de la R crítica de { $critical }, subamortiguado: la corriente oscila a ω_d = { $ringing } (Q = { $q }), decreciendo como e^(−αt) con α = { $alpha }; nunca supera { $bound }.
        [critical] R = { $resistance }, igual a la resistencia crítica, amortiguamiento crítico: un único pulso de corriente (negativo, el condensador se descarga) que vuelve a cero sin invertirse; nunca supera { $bound }.
       *[overdamped] R = { $resistance }, por encima de la R crítica de { $critical }, sobreamortiguado: un pulso lento de corriente (negativo, el condensador se descarga) sin invertirse, constante de tiempo lenta { $time }.
    }
rlc-describe-voltage = { $regime ->
        [undamped] R = { $resistance }, no amortiguado (un circuito LC sin pérdidas): la tensión del condensador oscila entre +{ $voltage } y −{ $voltage } indefinidamente a ω₀ = { $frequency }.
        [underdamped] R = { $resistance }, por debajo de la R crítica de { $critical }, subamortiguado: la tensión del condensador { $reversal ->
            [slight] se invierte solo ligeramente (como mucho un { $rebound } de V₀, dentro de la banda)
            [count] { $crossings ->
                [one] invierte su polaridad una vez antes de establecerse
               *[other] invierte su polaridad { $crossings } veces antes de establecerse
            }
           *[never] nunca invierte su polaridad
        } y { $settles ->
            [yes] queda dentro del 5 % de V₀ tras { $time }
           *[no] nunca se establece
        }.
        [critical] R = { $resistance }, igual a la resistencia crítica, amortiguamiento crítico: el condensador se vacía lo más rápido posible sin invertirse; { $settles ->
            [yes] queda dentro del 5 % de V₀ tras { $time }
           *[no] nunca se establece
        }.
       *[overdamped] R = { $resistance }, por encima de la R crítica de { $critical }, sobreamortiguado: el condensador se descarga lentamente sin invertirse; { $settles ->
            [yes] queda dentro del 5 % de V₀ tras { $time }
           *[no] nunca se establece
        }.
    }

### analogy

analogy-axis-response = respuesta normalizada
analogy-axis-energy = energía
analogy-series-x = x/x₀ masa
analogy-series-q = q/q₀ circuito
analogy-series-v = v/(x₀ωₙ) masa
analogy-series-i = i/(q₀ω₀) circuito
analogy-series-spring = ½kx² resorte
analogy-series-capacitor = ½q²/C condensador
analogy-series-mass = ½mv² masa
analogy-series-inductor = ½Li² bobina
analogy-series-total-mass = total, masa
analogy-series-total-circuit = total, circuito
analogy-caption-mechanical = mecánico
analogy-caption-electrical = eléctrico
analogy-schematic-title = Gemelos mecánico y eléctrico
analogy-describe-responses = { $regime } (ζ = { $zeta }): coinciden la x/x₀ mecánica y la q/q₀ eléctrica, así como la velocidad v/(x₀ωₙ) y la corriente i/(q₀ω₀) ({ $same ->
        [exact] idénticas hasta la última cifra
       *[close] diferencia máxima { $difference }
    }); { $motion ->
        [decaying] ambas oscilan a ω_d = { $frequency } y decaen con constante de tiempo 1/(ζωₙ) = { $time }
        [lasting] ambas oscilan indefinidamente a ω₀ = ωₙ = { $frequency }
       *[creeping] ambas vuelven lentamente al reposo sin oscilar
    }.
analogy-describe-energy = En t = 0, toda la energía, { $energy }, está almacenada en el resorte, e igualmente en el condensador. { $exchange ->
        [swings] Pasa a la masa (bobina), como mucho { $peak } a la vez, y vuelve, dos veces por ciclo
       *[passes] Sin oscilar, como mucho { $peak } pasa por la masa (bobina)
    }; { $loss ->
        [none] sin amortiguador (resistencia) sigue toda ahí tras { $time }
       *[heat] el amortiguador c (resistencia R) la convierte en calor y quedan { $left } ({ $percent }) tras { $time }
    }. Las curvas mecánica y eléctrica coinciden.
analogy-schematic = En t = { $time }: la masa está desplazada { $displacement } y se mueve a { $velocity }; el condensador tiene { $charge } y la corriente es { $current }. Los mismos números en otras unidades.

### universality

universality-axis-response = respuesta normalizada y/y₀
universality-axis-time = tiempo normalizado ωₙt
universality-series-critical = ζ = 1 (crítico), como referencia
universality-schematic-title = Máquinas A y B
universality-match-off = desactivado
universality-match-on = activado: B tiene la ωₙ y la ζ de A
universality-match-too-light = no alcanzable: con sus demás parámetros fijos, B no puede bajar de ζ = { $zeta_min }; A tiene ζ = { $zeta }
universality-match-out-of-range = no alcanzable dentro de los controles: B necesitaría { $symbol } = { $value }, fuera de { $low } … { $high }
universality-match-impossible = no alcanzable: A no tiene frecuencia natural
universality-describe-normalised = Soltadas desde el reposo: A ({ $machine_a }, ζ = { $zeta_a }) { $behaviour_a ->
        [forever] oscila indefinidamente
        [dies-away] oscila y se extingue
        [fastest] vuelve lo más rápido posible sin sobrepasar el equilibrio
       *[creeps] vuelve lentamente sin sobrepasar el equilibrio
    }; B ({ $machine_b }, ζ = { $zeta_b }) { $behaviour_b ->
        [forever] oscila indefinidamente
        [dies-away] oscila y se extingue
        [fastest] vuelve lo más rápido posible sin sobrepasar el equilibrio
       *[creeps] vuelve lentamente sin sobrepasar el equilibrio
    }. { $relation ->
        [coincide] Las dos curvas coinciden (diferencia máxima { $gap }).
       *[differ] Las curvas difieren hasta en { $gap } de y₀.
    }{ $thermal ->
        [yes] { " " }Un sistema térmico de dos capacidades no puede oscilar: su ζ supera 1 con cualesquiera capacidades y resistencias.
       *[no] { "" }
    }
universality-describe-realtime = Tiempo real durante { $window }: escala de tiempo 1/ωₙ de A { $scale_a }, de B { $scale_b }; { $pace ->
        [faster] B va { $factor } veces más rápido que A
        [slower] B va { $factor } veces más lento que A
       *[same] B sigue el paso de A exactamente
    }.
universality-schematic = En t = { $time }: A, { $machine_a }: { $coordinate_a } = { $value_a }; B, { $machine_b }: { $coordinate_b } = { $value_b }.
### quarter-car

quarter-car-legend-comfort = confort { $low } y { $high }
quarter-car-legend-performance = deportivo { $low } y { $high }
quarter-car-legend-critical = crítico { $zeta } (×)
quarter-car-legend-overdamped = sobreamortiguado { $zeta } (●)
quarter-car-group = { $group ->
        [comfort] confort
        [performance] deportivo
        [critical] crítico
       *[overdamped] sobreamortiguado
    }
quarter-car-crossings = { $count ->
        [0] no cruza el equilibrio
        [one] cruza el equilibrio una vez antes de establecerse
       *[other] cruza el equilibrio { $count } veces antes de establecerse
    }
quarter-car-crossings-inside-band = se establece antes de cruzar el equilibrio (su rebote queda dentro de la banda)
quarter-car-settles-after = queda dentro de ±{ $band } de x₀ alrededor del reposo tras { $time }
quarter-car-does-not-settle = no se establece
quarter-car-rebound = rebote máximo del { $rebound } en { $time }
quarter-car-no-rebound = sin rebote
quarter-car-describe-design = Este diseño (ζ = { $zeta }, { $regime }): { $crossings }, { $settling }, { $rebound }.
quarter-car-describe-undamped = Este diseño (ζ = 0, no amortiguado): oscila indefinidamente entre ±{ $amplitude } a { $frequency }.
quarter-car-describe-unsettled = Este diseño ({ $regime }): no se establece.
quarter-car-list-separator = {"; "}
quarter-car-describe-response = { $design } Ajustes predefinidos en este vehículo, con establecimiento en ±{ $band } de x₀: { $family }.
quarter-car-member-settles = { $group } ζ = { $zeta } en { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } no se establece
quarter-car-two-sentences = { $first } { $second }
quarter-car-settling-fastest = Tiempo de establecimiento de la respuesta libre en ±{ $band } de x₀ frente a ζ en este vehículo: el más rápido es ζ = { $zeta } ({ $time }), justo después de un salto; baja de golpe cada vez que un rebote queda dentro de la banda.
quarter-car-settling-curve = Tiempo de establecimiento de la respuesta libre en ±{ $band } de x₀ frente a ζ.
quarter-car-settling-design = Este diseño, ζ = { $zeta }, se establece en { $time }.
quarter-car-settling-design-never = Este diseño, ζ = { $zeta }, nunca se establece.
quarter-car-sensitivity-range = Con la masa suspendida entre { $low } y { $high } (±{ $variation }) y el mismo amortiguador y resorte, ζ va de { $min } a { $max } (nominal { $nominal }); la estimación lineal es de { $linear_min } a { $linear_max }.
quarter-car-sensitivity-undefined = El intervalo del coeficiente de amortiguamiento no está definido para este diseño.
quarter-car-sensitivity-inside = El ζ de establecimiento más rápido, { $zeta }, está dentro de este intervalo: las cargas que llevan ζ por debajo de él se establecen notablemente más tarde.
quarter-car-sensitivity-outside = El ζ de establecimiento más rápido, { $zeta }, está fuera de este intervalo.
quarter-car-schematic = Cuarto de vehículo en t = { $time }: la carrocería está a { $displacement } del reposo ({ $side ->
        [above] por encima
       *[below] por debajo
    }), carretera fija.
quarter-car-settling-title = Tiempo de establecimiento en ±{ $band } de x₀ frente a ζ
quarter-car-axis-zeta = coeficiente de amortiguamiento ζ
quarter-car-axis-zeta-fastest = coeficiente de amortiguamiento ζ (a trazos: ζ más rápido = { $zeta })
quarter-car-axis-settling-time = tiempo de establecimiento t_s
quarter-car-axis-sprung-mass = masa suspendida m
quarter-car-fastest = ζ más rápido = { $zeta }
quarter-car-this-design = este diseño
quarter-car-nominal = nominal
quarter-car-road = carretera
quarter-car-band-label = ±{ $band } de x₀
quarter-car-series-design = este diseño, ζ { $zeta }

### quarter-car-2dof

quarter-car-2dof-describe-motion = Sobre { $road ->
        [bump] un resalto
        [step] un escalón
        [sine] una carretera sinusoidal
       *[random] una carretera aleatoria
    } (altura máxima de la carretera { $road_peak }), la carrocería se mueve como mucho { $body } (en { $body_time }) y la rueda { $wheel } (en { $wheel_time }).
quarter-car-2dof-describe-acceleration = La aceleración de la carrocería alcanza un pico de { $peak } ({ $peak_g } g); en la marcha desde el reposo, de 0 a { $window }, su valor RMS es { $rms }.
quarter-car-2dof-describe-tyre-lift-off = La deflexión del neumático (rueda sobre la carretera, positiva = neumático descargándose) va de { $low } a { $high }, con un valor RMS de { $rms }; alcanza la deflexión estática { $limit } por primera vez a los { $time }, donde la fuerza del neumático cae a cero y la rueda despega de la carretera: despegues { $lift_offs }; tiempo en el aire { $airborne }.
quarter-car-2dof-describe-tyre-contact = La deflexión del neumático (rueda sobre la carretera, positiva = neumático descargándose) va de { $low } a { $high }, con un valor RMS de { $rms }; queda por debajo de la deflexión estática, { $limit }, así que el neumático mantiene el contacto.
quarter-car-2dof-describe-frf = Respuesta en frecuencia por unidad de altura de la carretera, en ejes logarítmicos. La carrocería sigue las ondulaciones lentas (razón 1), tiene un pico de { $body_peak } cerca del rebote de la carrocería, { $body_frequency }, y queda aislada por encima: { $at_20 } a 20 Hz. La deflexión del neumático tiene un pico de { $tyre_peak } cerca del salto de la rueda, { $tyre_frequency }.
quarter-car-2dof-schematic = Cuarto de vehículo en t = { $time }: carrocería { $body }, rueda { $wheel }, carretera { $road } (dibujadas a una escala común).
quarter-car-2dof-schematic-title = Esquema
quarter-car-2dof-axis-height = altura desde el equilibrio
quarter-car-2dof-axis-acceleration = aceleración z_s″
quarter-car-2dof-axis-tyre-deflection = deflexión del neumático z_u − u
quarter-car-2dof-axis-frequency = frecuencia f
quarter-car-2dof-axis-magnitude = magnitud por unidad de altura de la carretera
quarter-car-2dof-series-road = carretera u
quarter-car-2dof-series-wheel = rueda z_u
quarter-car-2dof-series-body = carrocería z_s
quarter-car-2dof-series-body-acceleration = aceleración de la carrocería
quarter-car-2dof-series-rms = ± RMS
quarter-car-2dof-series-lift-off = despegue (deflexión estática)
quarter-car-2dof-series-off-road = en el aire
quarter-car-2dof-series-body-gain = carrocería/carretera
quarter-car-2dof-series-tyre-gain = defl. neumático/carretera
quarter-car-2dof-marker-road = carretera
### paper

paper-unavailable = la demostración de esta figura no está disponible
paper-pending-plot = se dibuja cuando termine de cargarse la aplicación completa
paper-pending-mark = cargando…
paper-pending-value = …
paper-pending = Se comprueba en cuanto termina de cargarse la aplicación completa, en un momento.
paper-figure = Figura { $number }
paper-section = Sección { $number }
paper-section-figure = Sección { $section }, figura { $figure }
paper-near-agrees = La demostración calcula { $computed }, que coincide con el valor del artículo, { $claimed }, dentro del redondeo (tolerancia ±{ $tolerance }).
paper-near-differs = La demostración calcula { $computed }, y no el valor del artículo, { $claimed } (tolerancia ±{ $tolerance }).
paper-below-agrees = La demostración calcula { $computed }, por debajo de la cota de { $bound } del artículo.
paper-below-differs = La demostración calcula { $computed }, por encima de la cota de { $bound } del artículo.
paper-range = { $low } a { $high }
paper-range-agrees = La demostración calcula de { $low } a { $high }, como dice el artículo.
paper-range-differs = La demostración calcula de { $low } a { $high }, y no el intervalo del artículo.
paper-peak = El máximo de |H(r)| hallado por búsqueda está en r = { $found }, donde la fórmula da { $formula }.
paper-slope = Con el paso del artículo, h = { $step }, y cinco reducciones a la mitad (hasta { $smallest }), la pendiente ajustada es { $slope }.
paper-reason-context = { $verdict } { $context }
paper-exhibit-fig1a = Respuesta libre del cuarto de vehículo (m = 300 kg, k = 24 kN/m, x₀ = 60 mm) con los ajustes de confort, prestaciones, crítico y sobreamortiguado.
paper-exhibit-fig1b = Tiempo de establecimiento frente al coeficiente de amortiguamiento, con su mínimo.
paper-exhibit-fig2a = Corriente en el circuito RLC en serie (L = 0,5 H, C = 20 mF, V₀ = 12 V) mientras la resistencia recorre los regímenes.
paper-exhibit-fig2b = Tensión del condensador del mismo circuito.
paper-exhibit-fig3a = Módulo de la respuesta en frecuencia para una familia de coeficientes de amortiguamiento.
paper-exhibit-fig3b = Fase de la respuesta en frecuencia.
paper-exhibit-fig4a = Euler y RK4 frente a la respuesta exacta de un oscilador poco amortiguado (ζ = 0,05, ωₙ = 2 rad/s) con h = 0,3 s.
paper-exhibit-fig4b = Error máximo frente al paso en ejes log–log, con las pendientes.
paper-exhibit-fig5 = Una ecuación en muchas máquinas: sistemas mecánicos, eléctricos y de otros tipos con la misma ecuación a·y'' + b·y' + c·y = f(t).
paper-exhibit-table1 = La analogía mecánico–eléctrica: masa ↔ inductancia, amortiguador ↔ resistencia, resorte ↔ 1/capacidad.
paper-exhibit-table2 = Los regímenes de amortiguamiento: condición, raíces, comportamiento y ejemplos.
paper-exhibit-table3 = Los métodos de integración comparados: error, orden y estabilidad con un mismo paso.
paper-claim-fig1-zeta-optimum = Un coeficiente de amortiguamiento de alrededor de 0,7 da el menor tiempo de establecimiento (banda del 5 %).
paper-claim-sec3-natural-frequency = La frecuencia natural del cuarto de vehículo es de unos 8,9 rad/s (unos 1,4 Hz).
paper-claim-sec4-critical-resistance = El circuito tiene amortiguamiento crítico con R = 2√(L/C) = 10 Ω.
paper-claim-fig3-q-factor = Q = 10 con ζ = 0,05.
paper-claim-fig3-q-factor-light = Q = 50 con ζ = 0,01.
paper-claim-sec5-peak-frequency = La respuesta tiene su pico en ω = ωₙ√(1 − 2ζ²), justo por debajo de ωₙ (comprobado con ζ = 0,1).
paper-claim-fig4-euler-error = Con h = 0,3 s, el error máximo de Euler es de unos 0,08.
paper-claim-fig4-rk4-error = Con h = 0,3 s, el error máximo de RK4 es menor que 0,001.
paper-claim-fig4-euler-slope = El error de Euler cae con pendiente ≈ 1 en el gráfico log–log.
paper-claim-sec7-mass-tolerance = Una incertidumbre de ±10 % en la masa suspendida lleva ζ = 1,0 a un valor entre 0,91 y 1,10.
paper-claim-fig1-zeta-optimum-context = Con una banda del 2 %, el ζ que se establece más rápido es, en cambio, { $value }.
paper-claim-sec3-natural-frequency-context = En hercios: fₙ = { $value }.
paper-claim-fig4-euler-error-context = Euler es inestable con este paso: |1 + hλ| = { $value } por paso, así que su error crece sin límite.
paper-claim-fig4-rk4-error-context = RK4 es estable con este paso (|R(hλ)| = { $value } por paso), pero en toda la ventana su error supera la cota.
paper-claim-fig4-euler-slope-context = El orden ajustado con pasos pequeños, donde el error es asintótico, es { $value }.
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) varía como 1/√m, así que una variación de ±10 % en la masa lo mueve solo alrededor de un ±5 % (ωₙ baja a { $value } con +10 %).
### resonance

resonance-axis-ratio = razón de frecuencias r = ω/ωₙ
resonance-axis-amplification = amplificación |H| = X/(F₀/k)
resonance-axis-magnitude-db = magnitud 20·log₁₀|H|
resonance-axis-phase = fase ∠H (retraso de x respecto de F)
resonance-plot-magnitude-db = Amplificación |H(r)| en dB
resonance-family = familia ζ = { $from } … { $to }
resonance-current = ζ actual = { $zeta }
resonance-drive = excitación r = { $ratio }
resonance-peak = pico
resonance-quadrature = −90° en r = 1
resonance-legend-width = anchura de media potencia r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2 hasta r = { $upper }
resonance-legend-cutoff = corte a −3 dB r = { $upper }
resonance-band-width = puntos de media potencia (|H| = |H|max/√2) en r = { $lower } y { $upper }: anchura del pico r₂ − r₁ = { $width }
resonance-band-broad = |H| queda por encima de |H|max/√2 desde r = 0 hasta r = { $upper }: el pico no tiene punto inferior de media potencia, así que su anchura de media potencia no está definida
resonance-band-cutoff = |H| cae a 1/√2 de su valor estático (−3 dB) en la frecuencia de corte r = { $upper }; sin pico no hay anchura de media potencia
resonance-peak-at = pico de resonancia { $gain } en r = { $ratio }
resonance-no-peak = sin pico de resonancia (ζ ≥ 1/√2): |H| solo decrece desde 1 en r = 0
resonance-describe-magnitude = { $view ->
        [db] Magnitud en dB para ζ = { $zeta }: { $peak }; { $band }. A la frecuencia de excitación, r = { $drive }, la amplificación es { $gain }.
       *[linear] Magnitud para ζ = { $zeta }: { $peak }; { $band }. A la frecuencia de excitación, r = { $drive }, la amplificación es { $gain }.
    }
resonance-describe-phase = Fase del desplazamiento respecto de la fuerza para ζ = { $zeta }: 0° a baja frecuencia, −90° en r = 1 para cualquier coeficiente de amortiguamiento, hacia −180° por encima de la resonancia; cuanto menor es ζ, más brusco es el cambio. A la frecuencia de excitación, r = { $drive }, el retraso es { $degrees } ({ $radians } rad).
resonance-envelope = envolvente ±E(t)
resonance-steady-amplitude = amplitud permanente ±X
resonance-describe-time-growing = Excitado desde el reposo en r = { $ratio } (ω = { $omega }) durante { $span }: sin régimen permanente; la amplitud crece hasta alcanzar { $largest }.
resonance-describe-time = { $case ->
        [beats] Excitado desde el reposo en r = { $ratio } (ω = { $omega }) durante { $span }: los movimientos libre y forzado baten con periodo { $period } (constante de tiempo del decaimiento { $tau }), hacia la amplitud permanente { $amplitude }, con un retraso respecto de la fuerza de { $lag }. Máxima excursión representada: { $largest }.
        [build-up] Excitado desde el reposo en r = { $ratio } (ω = { $omega }) durante { $span }: en resonancia la amplitud crece hacia la amplitud permanente { $amplitude } con constante de tiempo 1/(ζωₙ) = { $tau }, con un retraso respecto de la fuerza de { $lag }. Máxima excursión representada: { $largest }.
       *[transient] Excitado desde el reposo en r = { $ratio } (ω = { $omega }) durante { $span }: tras un transitorio (constante de tiempo { $tau }) se establece en la amplitud permanente { $amplitude }, con un retraso respecto de la fuerza de { $lag }. Máxima excursión representada: { $largest }.
    }
resonance-fixed-base = base fija
resonance-schematic = Masa sobre resorte y amortiguador sobre una base fija, empujada por la fuerza F(t) = { $force } (flecha sobre la masa) en t = { $time }: desplazada { $displacement } del reposo.
resonance-beats-visible = visibles
resonance-beats-no-free-oscillation = ninguno (sin oscilación libre, ζ ≥ 1)
resonance-beats-no-drive = ninguno (fuerza constante)
resonance-beats-same-frequency = ninguno (excitado a ω_d)
resonance-beats-too-fast = ninguno (tan rápido como la oscilación)
resonance-beats-dies-out = ninguno (el movimiento libre se extingue antes)

### flutter

flutter-no-oscillation = sin oscilación
flutter-series-h-section = sección en H de 1940 (aprox. didáctica)
flutter-series-box = cajón aerodinámico (placa plana, Theodorsen)
flutter-series-simplest = A₂* equivalente a la imagen más simple
flutter-series-simplest-line = imagen más simple ζ_s − g·U
flutter-axis-reduced-velocity = velocidad reducida U/(f·B) = 2π/K
flutter-axis-wind-speed = velocidad del viento U
flutter-axis-effective-damping = coeficiente de amortiguamiento efectivo ζ_eff
flutter-axis-twist = giro θ
flutter-threshold = umbral 4Iζ_s/(ρB⁴) = { $value }
flutter-upper-pole = polo superior
flutter-lower-pole = polo inferior
flutter-amplitude = amplitud ±a(t)
flutter-limit-cycle = ciclo límite ±{ $amplitude }
flutter-describe-derivative = A₂* frente a la velocidad reducida para { $model ->
        [h] la sección en H de 1940 (aproximación didáctica, no valores medidos)
        [box] el cajón aerodinámico, idealizado como una placa plana delgada (valores exactos de Theodorsen en flujo potencial)
       *[simplest] la imagen más simple (el A₂* al que equivale su recta en U)
    }: el giro crece donde A₂* supera 4Iζ_s/(ρB⁴).
flutter-describe-derivative-now = { $description } Con U = { $speed } (K = { $k }, U/(fB) = { $reduced_velocity }), A₂* = { $a2 }, { $side ->
        [above] por encima del
       *[below] por debajo del
    } umbral { $threshold }.
flutter-describe-damping = Coeficiente de amortiguamiento efectivo de { $model ->
        [h] la sección en H de 1940
        [box] el cajón aerodinámico
       *[simplest] la imagen más simple
    } desde ζ_s = { $zeta_s } con aire en calma; { $crossing ->
        [inside] se anula a la velocidad crítica { $speed }
        [beyond] solo se anularía a { $speed }, más allá del máximo representado, { $limit }
       *[never] nunca se anula hasta 100 m/s: el viento solo añade amortiguamiento
    }.
flutter-describe-damping-now = { $description } Con U = { $speed } vale { $zeta }, { $sign ->
        [positive] positivo (estable)
        [negative] negativo (flameo)
       *[zero] cero
    }.
flutter-describe-damping-still = { $description } Con este viento el tablero no oscila.
flutter-describe-locus = Par de polos al aumentar el viento: { $re_calm } ± { $im_calm }i 1/s con aire en calma, { $re_end } ± { $im_end }i 1/s a { $limit }, { $crosses ->
        [yes] cruzando el eje imaginario en U_crit
       *[no] sin cruzar nunca el eje imaginario
    }.
flutter-describe-locus-now = { $description } Con U = { $speed } los polos son { $re } ± { $im }i 1/s, en el semiplano { $side ->
        [right] derecho (inestable)
       *[left] izquierdo (estable)
    }.
flutter-oscillation = la oscilación
flutter-oscillation-at = la oscilación a { $frequency } Hz
flutter-describe-response = { $regime }: desde un giro inicial de { $twist }, { $oscillation } { $case ->
        [settling] crece hasta { $end } al final de la gráfica ({ $window }), y se estabiliza cerca del ciclo límite de { $limit } (el 90 % a los { $time })
        [slow] solo crece hasta { $end } al final de la gráfica ({ $window }); tardaría { $time } en alcanzar el 90 % del ciclo límite de { $limit }
        [settled] se estabiliza en el ciclo límite de { $limit } al final de la gráfica ({ $window })
        [grows] crece hasta { $end } al final de la gráfica ({ $window })
       *[dies] se reduce a { $end } al final de la gráfica ({ $window })
    }.
flutter-describe-response-torn = { $description } Un giro tan grande habría roto cualquier tablero mucho antes; la cota es solo un supuesto didáctico.
flutter-schematic-title = Sección del tablero
flutter-drawn-clipped = dibujado recortado a { $angle }
flutter-drawn-true-scale = dibujado a escala real
flutter-drawn-larger = dibujado { $factor } veces mayor
flutter-drawn-note = ({ $drawn })
flutter-schematic = Sección del tablero del puente en t = { $time }: girado { $twist } ({ $drawn }), viento de { $wind } desde la izquierda.
flutter-wind = viento U = { $speed }
### integrators

integrators-join = { "; " }
integrators-legend-dp45-order = DP45: { $order }
integrators-overflow-note = desbordamiento en t = { $time }
integrators-failed = falló
integrators-stable-yes = sí
integrators-stable-no = no
integrators-method-euler = Euler explícito
integrators-method-symplectic-euler = Euler simpléctico
integrators-method-heun = Heun
integrators-method-rk4 = RK4
integrators-legend-symplectic-euler = Euler simpl. ×
integrators-legend-euler = Euler
integrators-legend-heun = Heun
integrators-legend-dp45 = DP45 ● pasos
integrators-legend-growing = { $legend } ×{ $growth }/paso ↑
integrators-legend-order = { $legend }: { $order }
integrators-legend-no-fit = { $legend }: sin ajuste
integrators-legend-dp45-no-order = DP45: sin orden
integrators-series-exact = exacta
integrators-axis-error = error |x_num − x_exact|
integrators-axis-step = paso h
integrators-axis-max-error = error máximo
integrators-axis-re = parte real Re(hλ)
integrators-axis-im = parte imaginaria Im(hλ)
integrators-axis-evaluations = evaluaciones del segundo miembro N
integrators-limit-up-to = estable para h ≤ { $step }
integrators-limit-every = estable para todo h
integrators-limit-none = inestable para todo h
integrators-method-overflows = { $method } se desborda en t = { $time } (×{ $growth } por paso)
integrators-method-diverges = { $method } diverge (×{ $growth } por paso), error máximo { $error }
integrators-method-diverges-clipped = { $method } diverge (×{ $growth } por paso, recortado), error máximo { $error }
integrators-method-bounded = { $method } permanece acotado (×{ $growth } por paso), error máximo { $error }
integrators-dp45-words = DP45 dio { $steps ->
        [one] { $steps } paso
       *[other] { $steps } pasos
    } (tolerancia { $tolerance }), error máximo { $error }
integrators-dp45-failed = DP45 falló: { $reason }
integrators-failed-underflow = el paso se hizo demasiado pequeño para avanzar en t = { $time } (el problema puede ser demasiado rígido o singular)
integrators-failed-max-steps = se detuvo en t = { $time } tras { $steps } pasos
integrators-failed-non-finite = la solución se hizo infinita o indefinida en t = { $time } (pruebe un paso menor)
integrators-describe-response = Cada método frente a la oscilación amortiguada exacta durante { $duration } con h = { $step } ({ $steps } pasos). { $methods }. La gráfica muestra ±{ $range } de la amplitud exacta; las curvas que la sobrepasan se recortan en el borde.
integrators-describe-response-last = Cada método frente a la oscilación amortiguada exacta durante { $duration } con h = { $step } ({ $steps } pasos, el último de { $last } para terminar en T). { $methods }. La gráfica muestra ±{ $range } de la amplitud exacta; las curvas que la sobrepasan se recortan en el borde.
integrators-error-peak = { $method }: máximo { $error } en t = { $time }
integrators-error-peak-growing = { $method }: máximo { $error } en t = { $time }, creciente
integrators-error-none = { $method }: sin error finito
integrators-error-no-method = No hay ningún método activado.
integrators-describe-error = Error |x_num − x_exact| en escala logarítmica en los puntos de la malla de cada método (h = { $step }): { $methods }.
integrators-describe-error-clipped = Error |x_num − x_exact| en escala logarítmica en los puntos de la malla de cada método (h = { $step }): { $methods }. Los errores por encima de { $clip } se recortan en el borde superior.
integrators-fit = { $method }: pendiente ajustada { $slope } (h = { $from } … { $to })
integrators-fit-overflows = { $method }: pendiente ajustada { $slope } (h = { $from } … { $to }), se desborda para h ≥ { $limit }
integrators-no-fit = { $method }: sin ajuste (demasiado pocos puntos en el rango asintótico)
integrators-no-fit-overflows = { $method }: sin ajuste (demasiado pocos puntos en el rango asintótico), se desborda para h ≥ { $limit }
integrators-slope = pendiente { $order }
integrators-describe-convergence = Error máximo en { $points } puntos de control comunes frente al paso h, para hasta { $levels } tamaños de paso que se reducen a la mitad desde { $from } (como mucho { $budget } pasos por método en total, { $euler_budget } para Euler explícito; los pasos más finos se omiten). { $methods }. Cada orden se ajusta solo en el rango asintótico, dibujado como el segmento grueso: los pasos más finos cuyas pendientes locales coinciden con un margen de { $spread }, con errores por debajo del { $ceiling } y por encima de 1e-10 de x₀. Las pendientes de referencia 1 y 4 van punteadas; el h actual es la línea vertical discontinua. DP45 no tiene un único h: véase la gráfica de trabajo–precisión.
integrators-off-scale = { $name } = { $value } (fuera de escala)
integrators-path = hλ al crecer h
integrators-z-real-pair = z = hλ = { $z1 } y { $z2 }
integrators-region-inside = { $method }: dentro de su región, |R| = { $growth }, { $limit }
integrators-region-outside = { $method }: fuera de su región, |R| = { $growth }, { $limit }
integrators-describe-stability = Regiones de estabilidad |R(z)| ≤ 1 en el plano complejo de z = hλ (el interior de cada curva cerrada; la del método de Euler explícito es el disco |1 + z| ≤ 1). Los dos polos del sistema con h = { $step } dan { $z }. { $methods }. El método de Euler simpléctico no es una aplicación escalar R(z): su matriz de paso 2×2 tiene radio espectral { $radius } en este caso; { $limit }. DP45 elige sus propios pasos y los mantiene estables.
integrators-work-words = { $method }: de { $error_first } con { $work_first } evaluaciones a { $error_last } con { $work_last }
integrators-describe-work = Error máximo frente al trabajo que costó, contado en evaluaciones del segundo miembro f, en ejes log–log, para cada método: los de paso fijo con los tamaños de paso del estudio de convergencia (error en sus puntos de control comunes), DP45 con tolerancias de { $from } … { $to } (error en sus pasos aceptados). Más abajo es más preciso, más a la izquierda es más barato; un método de orden p cae con pendiente −p; las ejecuciones de DP45 son puntos donde la tolerancia fija sus pasos y cruces donde los fija la estabilidad. { $methods }.
integrators-provisional = Provisional: a partir de un estudio grueso (como mucho { $budget } pasos por método, { $euler_budget } para Euler explícito; DP45 hasta { $tol }) mientras se calcula el completo ({ $full_budget } y { $full_euler_budget } pasos; DP45 hasta { $full_tol }). { $description }
integrators-runs-provisional = Provisional: las integraciones hasta ahora, hasta t = { $until } de { $duration }, mientras se calcula el resto. { $description }
integrators-dp45-stability-runs = ejecuciones cuyos pasos fija la estabilidad (más del { $share } de los pasos en el { $fraction } o más de su mayor paso estable): { $count }/{ $runs }
integrators-dp45-order = DP45: orden observado { $order } (ajustado en { $from } … { $to } evaluaciones, donde la tolerancia fija sus pasos); { $runs }
integrators-dp45-no-order = DP45 no tiene orden observado: la estabilidad fija sus pasos, o quedan demasiado pocas ejecuciones en el rango asintótico; { $runs }

### nonlinear

nonlinear-effect-linear = lineal
nonlinear-effect-hardening = resorte rigidizante
nonlinear-effect-softening = resorte ablandante
nonlinear-effect-stick-slip = adherencia-deslizamiento
nonlinear-effect-bump-stop = impacto contra el tope
nonlinear-effect-asymmetric = amortiguador asimétrico
nonlinear-effect-several = varias a la vez
nonlinear-effect-escaped = escape
nonlinear-join = { "; " }
nonlinear-differ = difieren hasta { $deviation } en t = { $time }
nonlinear-first-swing = primera oscilación { $nonlinear } frente a { $linear } la lineal (razón { $ratio })
nonlinear-sticks-at = la fricción retiene la masa en { $position } desde { $time }
nonlinear-escapes = la simulación no lineal sale de la gráfica (|x| > { $limit }) en { $time }
nonlinear-describe-response = { $effect }: ambas empiezan juntas; { $clauses }.
nonlinear-describe-phase = Plano de fase: ambas trayectorias empiezan en x = { $x0 }, v = { $v0 }. La lineal describe una espiral hacia ({ $x_linear }, { $v_linear }); la no lineal termina en x = { $x_end }, v = { $v_end }, con velocidad máxima { $speed } frente a { $speed_linear } la lineal.
nonlinear-describe-spring = Fuerza restauradora frente a la extensión en ±{ $reach }: el resorte lineal es la recta k·x; en el recorrido máximo, { $travel }, la fuerza no lineal es { $force } frente a { $linear } la lineal{ $stops ->
        [yes] , con los topes añadiendo { $rate } más allá de ±{ $gap }.
       *[no] .
    }
nonlinear-describe-damper = Fuerza de amortiguador más fricción frente a la velocidad en ±{ $speed }: a +{ $speed } (rebote) vale { $rebound }, a −{ $speed } (compresión) { $compression }; el amortiguador medio del modelo lineal da ±{ $linear }{ $coulomb ->
        [yes] ; la fricción de deslizamiento añade un salto de ±{ $friction } en v = 0, y en reposo la fricción estática sostiene hasta ±{ $holding }.
       *[no] .
    }
nonlinear-axis-velocity-rebound = velocidad v (+ rebote)
nonlinear-series-stops = topes ±{ $gap }
nonlinear-series-linear = modelo lineal
nonlinear-series-nonlinear = no lineal (RK4)
nonlinear-marker-sticks = se pega
nonlinear-marker-start = inicio
nonlinear-series-linear-spring = k·x lineal
nonlinear-series-spring = k·x + k₃·x³ + topes
nonlinear-series-linear-damper = c̄·v lineal
nonlinear-series-damper = amortiguador + fricción
nonlinear-schematic = Cuarto de vehículo en t = { $time }: suspensión extendida { $extension }{ $stops ->
        [pressing] , apoyada en un tope.
        [clear] , sin tocar los topes.
       *[none] .
    }

### uncertainty

uncertainty-quantity-zeta = coeficiente de amortiguamiento ζ
uncertainty-quantity-f0 = frecuencia natural f0
uncertainty-quantity-q = factor de calidad Q
uncertainty-quantity-bandwidth = ancho de banda de media potencia
uncertainty-quantity-settling-time = tiempo de establecimiento de la respuesta libre (±5 %)
uncertainty-hist-title = Monte Carlo: { $quantity }
uncertainty-draws-provisional = { $draws } ({ $full } en camino)
uncertainty-band-nominal-mass = m nominal
uncertainty-band-lowest-corner = esquina de ζ mínimo
uncertainty-band-nominal = nominal
uncertainty-band-highest-corner = esquina de ζ máximo
uncertainty-never = nunca
uncertainty-band-suspension = Respuesta libre desde { $start } con la masa suspendida a +{ $percent } %, nominal y a −{ $percent } %
uncertainty-band-rlc = Tensión del condensador desde 1 V en la esquina de ζ mínimo, en la nominal y en la esquina de ζ máximo de la caja de tolerancias
uncertainty-ignored-rlc = Los controles del RLC se ignoran.
uncertainty-ignored-suspension = Los controles de la suspensión se ignoran.
uncertainty-zeta-undefined = ζ no está definido en un extremo del intervalo
uncertainty-zeta-spans = ζ abarca { $low }–{ $high }
uncertainty-describe-band = { $what }: { $zeta }; tiempos de establecimiento al 5 % (cruces): { $first }, { $second } y { $third }. { $ignored }
uncertainty-dist-normal = normales (tolerancia = 3σ)
uncertainty-dist-uniform = uniformes
uncertainty-spec-zeta = La ventana de especificación de ζ, { $low }–{ $high }, está marcada; el { $share } de los sorteos cumple toda la especificación.
uncertainty-spec-settling-time = El límite de especificación, { $limit }, está marcado.
uncertainty-no-finite = Ningún sorteo da un valor finito de { $quantity }.
uncertainty-describe-histogram = Histograma de { $quantity } en { $draws } sorteos { $distribution }: de { $low } a { $high }; percentil 5: { $p5 }; percentil 95: { $p95 }.{ $marked ->
        [yes] {" "}{ $spec }
       *[no] {""}
    }
uncertainty-provisional-title = { $title } (provisional)
uncertainty-provisional-description = Provisional: a partir de los primeros { $shown } sorteos mientras continúa la simulación de { $full }. { $description }
uncertainty-axis-capacitor-voltage = tensión del condensador v_C
uncertainty-settling-band = banda de establecimiento del 5 %
uncertainty-axis-draws = sorteos
uncertainty-series-bins = sorteos por intervalo ({ $bins } intervalos)
uncertainty-no-finite-values = ningún valor finito
uncertainty-spec-limit = límite de especificación
uncertainty-percentiles = percentiles 5 y 95

## La guía para docentes (docs/embedding.md y docs/parameters.<tag>.md)

guide-parameters-heading = Parámetros de cada demostración
guide-parameters-note = Los parámetros de URL de cada demostración, para enlaces e inserciones (véase la guía, docs/embedding.md, en inglés). Generado a partir de las declaraciones en Rust y del catálogo de este idioma; una prueba falla si esta lista y el código difieren.
guide-column-key = clave
guide-column-quantity = magnitud
guide-column-unit = unidad
guide-column-range = intervalo
guide-column-default = valor predeterminado
guide-log = logarítmico
guide-readouts-plots = Resultados (`data-readout`): { $readouts }. Gráficas (`plots=`): { $plots }.
### design

design-map-title = { $metric ->
        [settling-time] Establecimiento en ±{ $band } de x₀
        [peak-rebound] Rebote máximo (% de x₀)
        [accel-rms] a_w (W_k)
       *[peak-transmissibility] Transmisibilidad máxima |X/U|
    }: { $low } → { $high }
design-bar-label = { $metric ->
        [settling-time] tiempo de establecimiento en ±{ $band } de x₀ [s]
        [peak-rebound] rebote máximo [% de x₀]
        [accel-rms] a_w (RMS ponderada con W_k) [m/s²]
       *[peak-transmissibility] transmisibilidad máxima |X/U| [m/m]
    }{ $scale ->
        [log] , escala log.
       *[linear] {""}
    }
design-axis-spring-rate = rigidez del resorte k
design-axis-damper-rate = constante del amortiguador c
design-axis-settling-time = tiempo de establecimiento en ±{ $band } de x₀
design-axis-comfort = a_w (RMS ponderada con W_k)
design-marker-selected = seleccionado
design-marker-settled = establecido
design-series-column = k = { $k }, c variable
design-series-pareto-front = frente de Pareto
design-series-band = banda de establecimiento ±{ $band } de x₀
design-series-fastest = el más rápido de la malla
design-series-selected = diseño seleccionado
design-road = una carretera ISO 8608 de clase { $class } a { $speed }
design-with-road = { $value } (carretera de clase { $class }, { $speed })
design-grid-size = { $n } × { $n } = { $cells }
design-grid-size-provisional = { $n } × { $n } = { $cells } ({ $full } × { $full } en camino)
design-map-lowest = valor mínimo { $value } en k = { $k }, c = { $c }
design-map-no-cell = ninguna celda está definida
design-map-selected-settles = el diseño seleccionado, con ζ = { $zeta }, se establece en ±{ $band } de x₀ en { $time }
design-map-selected-unsettled = el diseño seleccionado, con ζ = { $zeta }, no se establece
design-map-no-selection = ningún diseño válido seleccionado
design-describe-map = { $metric ->
        [settling-time] Tiempo de establecimiento de la respuesta libre desde x₀ = { $x0 } en ±{ $band } de x₀,
        [peak-rebound] Rebote máximo de la respuesta libre desde x₀ = { $x0 }, en % de x₀,
        [accel-rms] Confort a_w (aceleración RMS de la carrocería ponderada con W_k) del cuarto de vehículo de dos grados de libertad (rueda de { $wheel }, neumático de { $tyre }), estacionaria en { $road },
       *[peak-transmissibility] Transmisibilidad máxima |X/U|
    } para k en { $k_span } y c en { $c_span } (malla de { $grid } × { $grid }, m = { $mass }): { $lowest }; { $selected }{ $outside ->
        [yes] {" "}(fuera del mapa)
       *[no] {""}
    }. Color desde morado oscuro ({ $low }) hasta amarillo ({ $high }){ $scale ->
        [log] {" "}en escala logarítmica
       *[linear] {""}
    }. Líneas a trazos de ζ constante para ζ = { $z1 }; { $z2 }; { $z3 }; { $z4 } y { $z5 }; × marca la celda mínima y ●, el diseño seleccionado.
design-describe-pareto = Frente de Pareto de { $count ->
        [one] { $count } diseño no dominado
       *[other] { $count } diseños no dominados
    }: desde el más rápido, que se establece en ±{ $band } de x₀ en { $fast_time } con a_w = { $fast_accel }, hasta el más suave, { $smooth_time } con a_w = { $smooth_accel }. { $selected } Confort a_w: la aceleración RMS de la carrocería ponderada con W_k del cuarto de vehículo de dos grados de libertad en { $road }.
design-pareto-selected = El diseño seleccionado se establece en ±{ $band } de x₀ en { $time } con a_w = { $accel }.
design-pareto-selected-unsettled = El diseño seleccionado no tiene tiempo de establecimiento.
design-pareto-empty = Ningún diseño de la malla tiene a la vez tiempo de establecimiento y valor de confort a_w.
design-describe-response = Diseño seleccionado (ζ = { $zeta }) soltado desde el reposo en x₀ = { $x0 } (respuesta libre, no a un escalón): rebota un { $rebound } de x₀ y queda dentro de ±{ $band } de x₀ tras { $time }.
design-describe-response-fastest = Diseño seleccionado (ζ = { $zeta }) soltado desde el reposo en x₀ = { $x0 } (respuesta libre, no a un escalón): rebota un { $rebound } de x₀ y queda dentro de ±{ $band } de x₀ tras { $time }; el diseño más rápido de la malla (k = { $k }, c = { $c }) se establece en { $fastest_time }.
design-response-unsettled = El diseño seleccionado no se establece.
design-provisional = Provisional: a partir de una malla gruesa de { $coarse } × { $coarse } mientras se calcula el barrido de { $full } × { $full }. { $description }

## Declared strings (generated from the demo declarations)

### regimes

regimes-title = Regímenes de amortiguamiento
regimes-summary = Respuesta libre desde x(0) = x₀, x′(0) = v₀. El coeficiente de amortiguamiento ζ decide el régimen: ζ = 0 no amortiguado, 0 < ζ < 1 subamortiguado, ζ = 1 amortiguamiento crítico, ζ > 1 sobreamortiguado, ζ < 0 amortiguamiento negativo (la respuesta crece). Los polos s = −ζωₙ ± ωₙ√(ζ² − 1) recorren un círculo de radio ωₙ, llegan al eje real en ζ = 1 y cruzan el eje imaginario en ζ = 0.
regimes-param-wn = frecuencia natural
regimes-param-zeta = coeficiente de amortiguamiento
regimes-param-x0 = desplazamiento inicial
regimes-param-v0 = velocidad inicial
regimes-readout-regime = régimen
regimes-readout-wn = frecuencia natural ωₙ
regimes-readout-zeta = coeficiente de amortiguamiento ζ
regimes-readout-wd = frecuencia amortiguada ω_d
regimes-readout-pole-re = parte real del polo
regimes-readout-pole-im = parte imaginaria del polo
regimes-plot-response = Respuesta libre x(t)
regimes-plot-poles = Polos en el plano s
regimes-preset-1 = No amortiguado ζ = 0
regimes-preset-2 = Subamortiguado ζ = 0,2
regimes-preset-3 = Amortiguamiento crítico ζ = 1
regimes-preset-4 = Sobreamortiguado ζ = 2
regimes-preset-5 = Amortiguamiento negativo ζ = −0,1
regimes-table-caption = Los regímenes de amortiguamiento
regimes-table-column-1 = régimen
regimes-table-column-2 = condición
regimes-table-column-3 = raíces s₁, s₂
regimes-table-column-4 = comportamiento
regimes-table-column-5 = ejemplos de ingeniería
regimes-table-undamped-1 = No amortiguado
regimes-table-undamped-2 = ζ = 0
regimes-table-undamped-3 = ±iωₙ, sobre el eje imaginario
regimes-table-undamped-4 = oscila indefinidamente a ωₙ
regimes-table-undamped-5 = péndulo ideal, circuito tanque LC
regimes-table-underdamped-1 = Subamortiguado
regimes-table-underdamped-2 = 0 < ζ < 1
regimes-table-underdamped-3 = −ζωₙ ± iω_d, par complejo
regimes-table-underdamped-4 = oscilación decreciente a ω_d
regimes-table-underdamped-5 = suspensión de automóvil (ζ ≈ 0,2–0,7), cuerda de guitarra
regimes-table-critically-damped-1 = Amortiguamiento crítico
regimes-table-critically-damped-2 = ζ = 1
regimes-table-critically-damped-3 = −ωₙ, raíz real doble
regimes-table-critically-damped-4 = retorno más rápido sin oscilar
regimes-table-critically-damped-5 = cierrapuertas, aguja de un instrumento analógico
regimes-table-overdamped-1 = Sobreamortiguado
regimes-table-overdamped-2 = ζ > 1
regimes-table-overdamped-3 = dos raíces reales negativas
regimes-table-overdamped-4 = retorno lento, sin oscilación
regimes-table-overdamped-5 = amortiguador hidráulico pesado, termómetro
regimes-table-negatively-damped-1 = Amortiguamiento negativo
regimes-table-negatively-damped-2 = ζ < 0
regimes-table-negatively-damped-3 = semiplano derecho
regimes-table-negatively-damped-4 = oscilación creciente
regimes-table-negatively-damped-5 = flameo (Tacoma Narrows), frenos que chirrían

### quarter-car

quarter-car-title = Suspensión de cuarto de vehículo
quarter-car-summary = Una esquina de un vehículo: la carrocería (masa suspendida m) sobre un resorte k y un amortiguador c encima de una carretera fija, desplazada x₀ y soltada desde el reposo (x′(0) = 0). c y ζ son dos caras del mismo amortiguador, c = 2ζ√(km): al mover uno, el otro lo sigue; cambiar m o k conserva el amortiguador, así que ζ cambia. Las curvas finas muestran los ajustes de manual en este vehículo: confort (ζ ≈ 0,3–0,4) rebota, deportivo (ζ ≈ 0,65–0,7) es el que antes se establece, y los ajustes crítico (ζ = 1) y sobreamortiguado vuelven sin rebote, pero más despacio. El tiempo de establecimiento salta cuando ζ pasa por los valores en los que un rebote queda dentro de la banda: el ζ más rápido está justo después de uno de esos saltos, así que una carga mayor puede desajustar un vehículo bien ajustado (vea la gráfica de la masa). El establecimiento se mide sobre esta respuesta libre: el tiempo de establecimiento es el último instante en que |x| vale banda·|x₀|; a partir de él la carrocería queda dentro de ±banda·|x₀| alrededor del reposo (no de la banda alrededor del valor final de una respuesta al escalón).
quarter-car-param-m = masa suspendida
quarter-car-param-k = rigidez del resorte
quarter-car-param-c = constante del amortiguador
quarter-car-param-zeta = coeficiente de amortiguamiento
quarter-car-param-x0 = desplazamiento inicial
quarter-car-param-band = banda de establecimiento alrededor del reposo, relativa a x₀
quarter-car-param-dm = variación de la masa suspendida
quarter-car-readout-regime = régimen
quarter-car-readout-wn = frecuencia natural ωₙ
quarter-car-readout-fn = frecuencia natural fₙ
quarter-car-readout-zeta = coeficiente de amortiguamiento ζ
quarter-car-readout-c = constante del amortiguador c en uso
quarter-car-readout-c-crit = amortiguamiento crítico 2√(km)
quarter-car-readout-wd = frecuencia amortiguada ω_d
quarter-car-readout-settling-time = tiempo de establecimiento t_s en ±banda·|x₀| (respuesta libre)
quarter-car-readout-overshoot = rebote máximo (respecto de x₀)
quarter-car-readout-peak-time = instante del rebote máximo
quarter-car-readout-zeta-argmin = ζ de establecimiento más rápido (respuesta libre, misma banda)
quarter-car-readout-settling-min = su tiempo de establecimiento
quarter-car-readout-zeta-lo = ζ con masa +dm %
quarter-car-readout-zeta-hi = ζ con masa −dm %
quarter-car-plot-response = Desplazamiento de la carrocería x(t)
quarter-car-plot-settling = Tiempo de establecimiento de la respuesta libre frente a ζ
quarter-car-plot-sensitivity = ζ al variar la masa suspendida
quarter-car-preset-1 = Confort ζ = 0,3
quarter-car-preset-2 = Confort ζ = 0,4
quarter-car-preset-3 = Deportivo ζ = 0,65
quarter-car-preset-4 = Deportivo ζ = 0,7
quarter-car-preset-5 = Crítico ζ = 1
quarter-car-preset-6 = Sobreamortiguado ζ = 2

### rlc

rlc-title = Circuito RLC serie
rlc-summary = Un condensador cargado a V₀ se conecta en t = 0 a un circuito con una bobina y una resistencia. La carga q obedece la misma ecuación que una masa sobre un resorte: L hace de masa, R de amortiguador y 1/C de resorte. Con R por debajo de la resistencia crítica 2√(L/C), la energía va y viene entre C y L y la corriente oscila a ω_d, decreciendo como e^(−αt), α = R/(2L); con R = 2√(L/C) el condensador se vacía lo más rápido posible sin invertirse; por encima, la descarga vuelve a ser más lenta. Q = 1/(2ζ) cuenta las oscilaciones, y R/L es el ancho de banda de media potencia de la resonancia de la corriente: con una tensión sinusoidal, |I|² supera la mitad de su máximo en una banda de exactamente R/L rad/s, para cualquier R. La corriente es negativa mientras el condensador se descarga (i = dq/dt).
rlc-param-R = resistencia
rlc-param-L = inductancia
rlc-param-C = capacidad
rlc-param-V0 = tensión inicial del condensador
rlc-readout-regime = régimen
rlc-readout-w0 = frecuencia de resonancia ω₀ = 1/√(LC)
rlc-readout-f0 = frecuencia de resonancia f₀
rlc-readout-alpha = tasa de decaimiento α = R/(2L)
rlc-readout-zeta = coeficiente de amortiguamiento ζ
rlc-readout-Q = factor de calidad Q = 1/(2ζ)
rlc-readout-bandwidth = ancho de banda de media potencia de la resonancia de corriente Δω = R/L
rlc-readout-R-crit = resistencia crítica 2√(L/C)
rlc-readout-wd = frecuencia de oscilación ω_d
rlc-readout-settling-time = v_C dentro del 5 % de V₀ tras
rlc-plot-current = Corriente i(t)
rlc-plot-voltage = Tensión del condensador v_C(t)
rlc-preset-1 = LC sin pérdidas, R = 0
rlc-preset-2 = Oscilante, R = 2 Ω
rlc-preset-3 = Subamortiguado, R = 5 Ω
rlc-preset-4 = Crítico, R = 10 Ω
rlc-preset-5 = Sobreamortiguado, R = 20 Ω

### analogy

analogy-title = Una ecuación, dos máquinas
analogy-summary = Una masa sobre un resorte y un amortiguador y un circuito serie bobina–resistencia–condensador obedecen la misma ecuación de segundo orden. En la analogía fuerza–tensión, masa m ↔ inductancia L, amortiguamiento c ↔ resistencia R, rigidez k ↔ 1/C, fuerza F ↔ tensión E y desplazamiento x ↔ carga q (así, velocidad ↔ corriente). Aquí el circuito recibe los mismos números que el mecanismo (L en H = m en kg, R en Ω = c en N·s/m, 1/C en 1/F = k en N/m, q₀ en C = x₀ en m), y ambos parten del reposo: al mover cualquier control cambian las dos máquinas a la vez, sus respuestas normalizadas siguen siendo una sola curva y la energía va y viene entre resorte y masa exactamente igual que entre condensador y bobina.
analogy-param-m = masa (≙ inductancia L)
analogy-param-c = amortiguamiento (≙ resistencia R)
analogy-param-k = rigidez del resorte (≙ 1/C)
analogy-param-x0 = desplazamiento inicial (≙ carga q₀)
analogy-readout-m = masa m
analogy-readout-L = inductancia L (≙ masa m)
analogy-readout-c = amortiguamiento c
analogy-readout-R = resistencia R (≙ amortiguamiento c)
analogy-readout-k = rigidez del resorte k
analogy-readout-elastance = elastancia 1/C (≙ k)
analogy-readout-compliance = flexibilidad 1/k (≙ C)
analogy-readout-C = capacidad C (≙ 1/k)
analogy-readout-x0 = desplazamiento inicial x₀
analogy-readout-q0 = carga inicial q₀ (≙ x₀)
analogy-readout-wn = frecuencia natural ωₙ = √(k/m)
analogy-readout-w0 = frecuencia de resonancia ω₀ = 1/√(LC) (≙ ωₙ)
analogy-readout-zeta = coeficiente de amortiguamiento ζ (ambos)
analogy-readout-regime = régimen (ambos)
analogy-readout-Q = factor de calidad Q (ambos)
analogy-readout-energy = energía almacenada ½kx₀² = ½q₀²/C
analogy-plot-responses = Respuestas normalizadas de ambas máquinas
analogy-plot-energy = Intercambio de energía
analogy-preset-1 = Resorte sin rozamiento ↔ circuito tanque LC (c = R = 0)
analogy-preset-2 = Amortiguamiento ligero ζ = 0,05
analogy-preset-3 = Crítico ζ = 1 (c = 2√(mk), R = 2√(L/C))
analogy-preset-4 = Sobreamortiguado ζ = 2
analogy-preset-5 = Pesado y blando: m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF
analogy-table-caption = La analogía fuerza–tensión: a·y″ + b·y′ + c·y = f(t) leída de dos maneras, con los valores actuales de ambas máquinas
analogy-table-column-1 = papel en la ecuación
analogy-table-column-2 = mecánico
analogy-table-column-3 = valor actual
analogy-table-column-4 = eléctrico
analogy-table-column-5 = valor actual
analogy-table-inertia-1 = inercia a
analogy-table-inertia-2 = masa m [kg]
analogy-table-inertia-4 = inductancia L [H]
analogy-table-dissipation-1 = disipación b
analogy-table-dissipation-2 = constante de amortiguamiento c [N·s/m]
analogy-table-dissipation-4 = resistencia R [Ω]
analogy-table-stiffness-1 = rigidez c
analogy-table-stiffness-2 = rigidez del resorte k [N/m]
analogy-table-stiffness-4 = elastancia 1/C [1/F]
analogy-table-compliance-1 = flexibilidad 1/c
analogy-table-compliance-2 = flexibilidad 1/k [m/N]
analogy-table-compliance-4 = capacidad C [F]
analogy-table-drive-1 = excitación f(t)
analogy-table-drive-2 = fuerza F [N]
analogy-table-drive-3 = 0: parte del reposo
analogy-table-drive-4 = tensión E [V]
analogy-table-drive-5 = 0: sin fuente en el circuito
analogy-table-coordinate-1 = coordenada y, inicialmente y₀
analogy-table-coordinate-2 = desplazamiento x, inicialmente x₀ [m]
analogy-table-coordinate-4 = carga q, inicialmente q₀ [C]
analogy-table-rate-1 = derivada y′
analogy-table-rate-2 = velocidad v = ẋ [m/s]
analogy-table-rate-3 = 0 al soltar
analogy-table-rate-4 = corriente i = q̇ [A]
analogy-table-rate-5 = 0 al soltar
analogy-table-natural-frequency-1 = frecuencia natural √(c/a)
analogy-table-natural-frequency-2 = ωₙ = √(k/m) [rad/s]
analogy-table-natural-frequency-4 = ω₀ = 1/√(LC) [rad/s]
analogy-table-damping-ratio-1 = coeficiente de amortiguamiento ζ = b/(2√(ac))
analogy-table-damping-ratio-2 = ζ = c/(2√(mk))
analogy-table-damping-ratio-4 = ζ = (R/2)·√(C/L)
analogy-table-quality-factor-1 = factor de calidad Q = √(ac)/b
analogy-table-quality-factor-2 = Q = √(mk)/c
analogy-table-quality-factor-4 = Q = √(L/C)/R
analogy-table-potential-energy-1 = almacenada por la rigidez
analogy-table-potential-energy-2 = resorte ½kx², al soltar ½kx₀² [J]
analogy-table-potential-energy-4 = condensador ½q²/C, al soltar ½q₀²/C [J]
analogy-table-kinetic-energy-1 = almacenada por la inercia
analogy-table-kinetic-energy-2 = masa ½mv² [J]
analogy-table-kinetic-energy-3 = 0 al soltar
analogy-table-kinetic-energy-4 = bobina ½Li² [J]
analogy-table-kinetic-energy-5 = 0 al soltar
analogy-table-power-lost-1 = potencia disipada
analogy-table-power-lost-2 = amortiguador c·v² [W]
analogy-table-power-lost-3 = 0 al soltar
analogy-table-power-lost-4 = resistencia R·i² [W]
analogy-table-power-lost-5 = 0 al soltar

### universality

universality-title = Una ecuación, muchas máquinas
universality-summary = Seis máquinas, una ecuación a·y″ + b·y′ + c·y = f(t). Elija una máquina para A y otra para B y ajuste cada una con sus propios parámetros físicos: cada una da sus propios a, b y c, en sus propias unidades, y con ellos una frecuencia natural ωₙ = √(c/a) y un coeficiente de amortiguamiento ζ = b/(2√(ac)). Soltada desde y₀ en reposo, la respuesta normalizada y/y₀ de una máquina frente a ωₙt depende solo de ζ, así que máquinas con igual ζ trazan una misma curva. Marque “igualar” y los parámetros de ajuste de B se calculan para que su ωₙ y su ζ igualen los de A: entonces B se comporta exactamente como A, segundo a segundo. El sistema térmico de dos capacidades nunca oscila: b² − 4ac = (τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂) > 0, así que su ζ > 1 sean cuales sean sus capacidades y resistencias: el calor no tiene inercia que lo lleve más allá del equilibrio.
universality-param-A = máquina A
universality-param-A-mass-spring = masa–resorte–amortiguador
universality-param-A-rlc = circuito RLC en serie
universality-param-A-u-tube = manómetro de tubo en U
universality-param-A-servo = servo de posición con motor de CC (control PD)
universality-param-A-storey = planta de edificio con movimiento del suelo
universality-param-A-thermal = sistema térmico de dos capacidades
universality-param-A-m = masa
universality-param-A-c = constante de amortiguamiento
universality-param-A-k = rigidez del resorte
universality-param-A-L = inductancia
universality-param-A-R = resistencia
universality-param-A-C = capacidad
universality-param-A-len = longitud de la columna de líquido
universality-param-A-bore = diámetro interior del tubo
universality-param-A-rho = densidad del líquido
universality-param-A-mu = viscosidad dinámica
universality-param-A-J = inercia del motor y la carga
universality-param-A-Kt = constante de par del motor
universality-param-A-Ra = resistencia del inducido
universality-param-A-Kp = ganancia proporcional
universality-param-A-Kd = ganancia derivativa
universality-param-A-mf = masa del forjado
universality-param-A-h = altura de planta
universality-param-A-EI = rigidez a flexión de cada uno de los 4 pilares
universality-param-A-cf = constante de amortiguamiento de la planta
universality-param-A-C1 = capacidad calorífica del cuerpo 1
universality-param-A-R1 = resistencia térmica, cuerpo 1 al entorno
universality-param-A-C2 = capacidad calorífica del cuerpo 2
universality-param-A-R2 = resistencia térmica, cuerpo 2 al cuerpo 1
universality-param-B = máquina B
universality-param-B-mass-spring = masa–resorte–amortiguador
universality-param-B-rlc = circuito RLC en serie
universality-param-B-u-tube = manómetro de tubo en U
universality-param-B-servo = servo de posición con motor de CC (control PD)
universality-param-B-storey = planta de edificio con movimiento del suelo
universality-param-B-thermal = sistema térmico de dos capacidades
universality-param-B-m = masa
universality-param-B-c = constante de amortiguamiento
universality-param-B-k = rigidez del resorte
universality-param-B-L = inductancia
universality-param-B-R = resistencia
universality-param-B-C = capacidad
universality-param-B-len = longitud de la columna de líquido
universality-param-B-bore = diámetro interior del tubo
universality-param-B-rho = densidad del líquido
universality-param-B-mu = viscosidad dinámica
universality-param-B-J = inercia del motor y la carga
universality-param-B-Kt = constante de par del motor
universality-param-B-Ra = resistencia del inducido
universality-param-B-Kp = ganancia proporcional
universality-param-B-Kd = ganancia derivativa
universality-param-B-mf = masa del forjado
universality-param-B-h = altura de planta
universality-param-B-EI = rigidez a flexión de cada uno de los 4 pilares
universality-param-B-cf = constante de amortiguamiento de la planta
universality-param-B-C1 = capacidad calorífica del cuerpo 1
universality-param-B-R1 = resistencia térmica, cuerpo 1 al entorno
universality-param-B-C2 = capacidad calorífica del cuerpo 2
universality-param-B-R2 = resistencia térmica, cuerpo 2 al cuerpo 1
universality-param-match = igualar: ajustar B para que se comporte como A (mismos ωₙ y ζ)
universality-readout-a-A = coeficiente de inercia a de A
universality-readout-b-A = coeficiente de amortiguamiento b de A
universality-readout-c-A = coeficiente de rigidez c de A
universality-readout-wn-A = frecuencia natural ωₙ de A
universality-readout-zeta-A = coeficiente de amortiguamiento ζ de A
universality-readout-regime-A = régimen de A
universality-readout-a-B = coeficiente de inercia a de B
universality-readout-b-B = coeficiente de amortiguamiento b de B
universality-readout-c-B = coeficiente de rigidez c de B
universality-readout-wn-B = frecuencia natural ωₙ de B
universality-readout-zeta-B = coeficiente de amortiguamiento ζ de B
universality-readout-regime-B = régimen de B
universality-readout-wn-ratio = razón de escalas de tiempo ωₙ(B)/ωₙ(A)
universality-readout-match = igualación
universality-plot-normalised = Respuestas normalizadas y/y₀ frente a ωₙt
universality-plot-realtime = Respuestas en tiempo real
universality-preset-1 = Masa–resorte y circuito RLC, igualados
universality-preset-2 = Manómetro de tubo en U y masa–resorte, igualados
universality-preset-3 = Planta de edificio ajustada como un servo
universality-preset-4 = Termómetro (dos capacidades) y masa–resorte, igualados
universality-preset-5 = Un sistema térmico no puede igualar a un oscilador
universality-table-caption = Una ecuación, muchas máquinas: qué son y, a, b y c
universality-table-column-1 = máquina
universality-table-column-2 = coordenada y
universality-table-column-3 = a
universality-table-column-4 = b
universality-table-column-5 = c
universality-table-column-6 = ωₙ
universality-table-column-7 = ζ
universality-table-mass-spring-1 = masa–resorte–amortiguador
universality-table-mass-spring-2 = desplazamiento x [m]
universality-table-mass-spring-3 = masa m [kg]
universality-table-mass-spring-4 = constante de amortiguamiento c [N·s/m]
universality-table-mass-spring-5 = rigidez del resorte k [N/m]
universality-table-mass-spring-6 = √(k/m)
universality-table-mass-spring-7 = c/(2√(km))
universality-table-rlc-1 = circuito RLC en serie
universality-table-rlc-2 = carga q [C]
universality-table-rlc-3 = inductancia L [H]
universality-table-rlc-4 = resistencia R [Ω]
universality-table-rlc-5 = 1/C [1/F]
universality-table-rlc-6 = 1/√(LC)
universality-table-rlc-7 = (R/2)·√(C/L)
universality-table-u-tube-1 = manómetro de tubo en U
universality-table-u-tube-2 = cambio de nivel h [m]
universality-table-u-tube-3 = ρAL [kg]
universality-table-u-tube-4 = 8πμL [N·s/m]
universality-table-u-tube-5 = 2ρgA [N/m]
universality-table-u-tube-6 = √(2g/L)
universality-table-u-tube-7 = 16μ/(ρd²ωₙ)
universality-table-servo-1 = servo de posición con motor de CC (control PD)
universality-table-servo-2 = error de ángulo θ [rad]
universality-table-servo-3 = J [kg·m²]
universality-table-servo-4 = K_t(K_t + K_d)/R_a [N·m·s/rad]
universality-table-servo-5 = K_t·K_p/R_a [N·m/rad]
universality-table-servo-6 = √(K_t·K_p/(R_a·J))
universality-table-servo-7 = ≥ K_t²/(2ωₙR_a·J), solo por la fuerza contraelectromotriz
universality-table-storey-1 = planta de edificio con movimiento del suelo
universality-table-storey-2 = deriva de planta u [m]
universality-table-storey-3 = masa del forjado m [kg]
universality-table-storey-4 = constante de amortiguamiento c [N·s/m]
universality-table-storey-5 = 12·4·EI/h³ [N/m]
universality-table-storey-6 = √(48EI/(m·h³))
universality-table-storey-7 = c/(2√(km))
universality-table-thermal-1 = sistema térmico de dos capacidades
universality-table-thermal-2 = exceso de temperatura T₂ [K]
universality-table-thermal-3 = R₁C₁R₂C₂ [s²]
universality-table-thermal-4 = R₁C₁ + R₂C₂ + R₁C₂ [s]
universality-table-thermal-5 = 1
universality-table-thermal-6 = 1/√(τ₁τ₂)
universality-table-thermal-7 = (τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) > 1

### resonance

resonance-title = Resonancia forzada
resonance-summary = Una masa de 1 kg sobre un resorte (k = ωₙ²·m) y un amortiguador (c = 2ζωₙ·m), en reposo, se excita desde t = 0 con F(t) = F₀·cos(ωt). En régimen permanente se mueve a la frecuencia de excitación con amplitud |H(r)|·F₀/k, retrasada respecto de la fuerza en la fase de H, donde r = ω/ωₙ. Un amortiguamiento ligero da un pico alto y estrecho cerca de r = 1 (altura ≈ Q = 1/(2ζ)). Su anchura de media potencia, r₂ − r₁ entre las dos razones de frecuencias en las que |H| = |H|max/√2, es ≈ 2ζ con amortiguamiento ligero; por encima de ζ ≈ 0,383 el punto inferior llega a r = 0 y la anchura no está definida, y por encima de ζ = 1/√2 no hay ningún pico. Excitada exactamente en resonancia, la amplitud crece a lo largo de unas pocas constantes de tiempo 1/(ζωₙ) sin batir; excitada cerca de ella, los movimientos libre y forzado baten entre sí hasta que la parte libre se extingue.
resonance-param-zeta = coeficiente de amortiguamiento
resonance-param-r = razón de frecuencias ω/ωₙ
resonance-param-wn = frecuencia natural
resonance-param-F0 = amplitud de la fuerza
resonance-param-view = escala de la magnitud
resonance-param-view-linear = |H| lineal
resonance-param-view-db = decibelios 20·log₁₀|H|
resonance-readout-peak-gain = pico de resonancia |H|max
resonance-readout-peak-ratio = pico en r = ω/ωₙ
resonance-readout-Q = factor de calidad Q = 1/(2ζ)
resonance-readout-peak-width = anchura de media potencia del pico de |H| r₂ − r₁ (ζ < 0,383)
resonance-readout-gain-at-r = ganancia |H(r)| a la frecuencia de excitación
resonance-readout-phase-at-r = fase ∠H(r) a la frecuencia de excitación
resonance-readout-amplitude = amplitud permanente X = |H|·F₀/k
resonance-readout-beat-period = periodo de batido 2π/|ω − ω_d| (mientras se ven batidos)
resonance-readout-beats = batidos en x(t)
resonance-plot-magnitude = Amplificación |H(r)|
resonance-plot-phase = Fase ∠H(r)
resonance-plot-time = Respuesta desde el reposo x(t)
resonance-preset-1 = En resonancia, ζ = 0,05
resonance-preset-2 = Batido cerca de la resonancia, r = 0,9
resonance-preset-3 = Sin pico, ζ ≈ 1/√2
resonance-preset-4 = Cuasiestático, r = 0,2
resonance-preset-5 = Aislamiento, r = 3

### integrators

integrators-title = Integradores numéricos y su error
integrators-summary = El oscilador libre integrado con el método de Euler explícito, Euler simpléctico, Heun (RK2) y RK4 clásico con un paso fijo h, y con Dormand–Prince 5(4) con paso adaptativo, cada uno comparado con la solución exacta. Un método de un paso multiplica cada modo por R(hλ) en cada paso: cuando |R| > 1, los números crecen por bien que el método se ajuste a la ecuación, y por eso el método de Euler explícito hace estallar un oscilador poco amortiguado salvo que h < 2ζ/ωₙ. Cuando es estable, reducir h a la mitad divide el error entre 2^p, donde p es el orden de convergencia del método: la gráfica de convergencia mide p. Desactivar un método oculta sus curvas; sus lecturas se siguen calculando.
integrators-param-zeta = coeficiente de amortiguamiento
integrators-param-wn = frecuencia natural
integrators-param-h = tamaño de paso
integrators-param-T = duración
integrators-param-x0 = desplazamiento inicial
integrators-param-tol = tolerancia de DP45 (relativa; absoluta tol·x₀)
integrators-param-euler = Euler explícito
integrators-param-symplectic-euler = Euler simpléctico
integrators-param-heun = Heun (RK2)
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4), adaptativo
integrators-readout-h-used = paso usado, salvo el último
integrators-readout-h-last = último paso, que termina la integración en T
integrators-readout-max-err-euler = error máximo, Euler explícito
integrators-readout-max-err-symplectic-euler = error máximo, Euler simpléctico
integrators-readout-max-err-heun = error máximo, Heun
integrators-readout-max-err-rk4 = error máximo, RK4
integrators-readout-max-err-dp45 = error máximo, DP45
integrators-readout-order-euler = orden de convergencia ajustado, Euler explícito
integrators-readout-order-symplectic-euler = orden de convergencia ajustado, Euler simpléctico
integrators-readout-order-heun = orden de convergencia ajustado, Heun
integrators-readout-order-rk4 = orden de convergencia ajustado, RK4
integrators-readout-order-dp45 = orden observado, DP45 (error frente a evaluaciones de f, donde la tolerancia fija los pasos)
integrators-readout-stable-euler = estable con este h, Euler explícito
integrators-readout-stable-symplectic-euler = estable con este h, Euler simpléctico
integrators-readout-stable-heun = estable con este h, Heun
integrators-readout-stable-rk4 = estable con este h, RK4
integrators-readout-growth-euler = crecimiento por paso |R(hλ)|, Euler explícito
integrators-readout-growth-symplectic-euler = crecimiento por paso (radio espectral), Euler simpléctico
integrators-readout-growth-heun = crecimiento por paso |R(hλ)|, Heun
integrators-readout-growth-rk4 = crecimiento por paso |R(hλ)|, RK4
integrators-readout-steps-dp45 = pasos aceptados por DP45
integrators-plot-response = Soluciones numéricas y la x(t) exacta
integrators-plot-error = Error a lo largo del tiempo
integrators-plot-convergence = Convergencia: error máximo frente al paso h
integrators-plot-work = Trabajo–precisión: error máximo frente a evaluaciones de f
integrators-plot-stability = Regiones de estabilidad y z = hλ
integrators-preset-1 = Poco amortiguado, h = 0,3 s
integrators-preset-2 = Euler explícito apenas estable, h = 0,04 s
integrators-preset-3 = RK4 más allá de su límite, h = 1,6 s
integrators-preset-4 = No amortiguado, h = 0,1 s
integrators-preset-5 = Rígido y sobreamortiguado, ζ = 2, ωₙ = 20
integrators-table-caption = Los métodos
integrators-table-column-1 = método
integrators-table-column-2 = orden p
integrators-table-column-3 = evaluaciones de f por paso
integrators-table-column-4 = factor de amplificación R(z)
integrators-table-column-5 = en un oscilador no amortiguado
integrators-table-euler-1 = Euler explícito
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = siempre crece: |R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = Euler simpléctico
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = matriz 2×2, no un R escalar
integrators-table-symplectic-euler-5 = error de energía acotado mientras ωh ≤ 2
integrators-table-heun-1 = Heun (RK2)
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = crece lentamente: |R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = RK4 clásico
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = amortigua ligeramente mientras ωh ≤ 2√2
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6 (la primera coincide con la última)
integrators-table-dp45-4 = adaptativo: h sigue la estimación del error
integrators-table-dp45-5 = estable: los pasos rechazados reducen h

### flutter

flutter-title = Flameo: el puente de Tacoma Narrows
flutter-summary = Un viento constante puede aportar energía a un tablero de puente que gira a través de su propio movimiento. Scanlan escribió el momento del viento sobre un tablero que gira con derivadas de flameo medidas en túneles de viento: A₂* multiplica la velocidad de giro (un término de amortiguamiento) y A₃* el giro (un término de rigidez), ambas funciones de la frecuencia reducida K = Bω/U. El coeficiente de amortiguamiento del tablero pasa a ser ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I): en la sección en H, poco aerodinámica, del tablero de Tacoma de 1940 A₂* cambia de signo al aumentar el viento, y en cuanto supera el umbral 4Iζ_s/(ρB⁴) cualquier pequeño giro crece a la frecuencia de torsión propia del tablero (cerca de 0,2 Hz): flameo, no resonancia; un viento constante no tiene ninguna frecuencia con la que coincidir, el movimiento crea su propia excitación. La frecuencia se obtiene por iteración a cada velocidad del viento, ya que K depende de ella. La teoría lineal deja crecer el giro sin fin; aquí se supone que el término de amortiguamiento del viento se reduce a la mitad con un giro θ_s, lo que acota el movimiento en un gran ciclo límite, como el 7 de noviembre de 1940, cuando con vientos de unas 42 mph el giro creció en menos de una hora hasta que el tablero se rompió. Declarado como tal: A₂* y A₃* de la sección en H son una aproximación didáctica, curvas suaves con la forma de los resultados publicados de túnel de viento (Scanlan y Tomko 1971; Billah y Scanlan 1991), no valores leídos de ellos; I, ζ_s y θ_s son supuestos. El cajón aerodinámico se idealiza como una placa plana delgada, cuyos A₂* y A₃* son exactos en flujo potencial (Theodorsen 1935): su A₂* sigue siendo negativo, así que nunca entra en flameo en este intervalo. La imagen más simple ζ_eff = ζ_s − g·U se mantiene para comparar.
flutter-param-U = velocidad del viento
flutter-param-model = modelo del momento del viento
flutter-param-model-scanlan = derivadas de flameo (Scanlan)
flutter-param-model-linear = imagen más simple: ζ_eff = ζ_s − g·U
flutter-param-section = sección del tablero
flutter-param-section-h = sección en H de 1940 (vigas de alma llena)
flutter-param-section-box = viga cajón aerodinámica
flutter-param-B = ancho del tablero
flutter-param-I = momento de inercia másico por unidad de longitud (supuesto para 1940)
flutter-param-f0 = frecuencia de torsión con aire en calma
flutter-param-zeta-s = coeficiente de amortiguamiento estructural (supuesto para 1940)
flutter-param-theta0 = giro inicial
flutter-param-theta-s = giro con el que el amortiguamiento del viento se reduce a la mitad (supuesto didáctico)
flutter-param-slope = imagen más simple: amortiguamiento perdido por m/s
flutter-readout-regime = régimen de un giro pequeño
flutter-readout-U-crit = velocidad crítica (de flameo) U_crit, buscada hasta 100 m/s
flutter-readout-zeta-eff = coeficiente de amortiguamiento efectivo ζ_eff de un giro pequeño
flutter-readout-growth-rate = tasa de crecimiento σ de un giro pequeño (< 0: decae)
flutter-readout-doubling-time = un giro pequeño se duplica cada
flutter-readout-frequency = frecuencia de torsión con viento f
flutter-readout-K = frecuencia reducida K = Bω/U
flutter-readout-reduced-velocity = velocidad reducida U/(f·B) = 2π/K
flutter-readout-A2 = derivada de flameo A₂*(K)
flutter-readout-A3 = derivada de flameo A₃*(K)
flutter-readout-limit-deg = amplitud del giro en el ciclo límite (con la cota supuesta θ_s)
flutter-readout-time-to-large = tiempo desde θ₀ hasta el 90 % del ciclo límite
flutter-readout-amplitude-end-deg = amplitud del giro al final de la gráfica
flutter-plot-derivative = Derivada de flameo A₂* y umbral de flameo
flutter-plot-damping = Amortiguamiento efectivo frente a la velocidad del viento
flutter-plot-locus = Lugar de las raíces al aumentar el viento
flutter-plot-response = Giro del tablero θ(t) a lo largo de minutos
flutter-preset-1 = Tacoma 1940, 10 m/s (estable)
flutter-preset-2 = Tacoma 1940, 19 m/s (día del colapso, ≈ 42 mph)
flutter-preset-3 = Tacoma 1940, vendaval de 30 m/s
flutter-preset-4 = Tablero de cajón aerodinámico, 19 m/s
flutter-preset-5 = Tablero de cajón aerodinámico, 40 m/s
flutter-preset-6 = Imagen más simple, 19 m/s (ζ_eff = ζ_s − g·U)
flutter-table-caption = El flameo no es resonancia
flutter-table-column-1 = caso
flutter-table-column-2 = qué lo impulsa
flutter-table-column-3 = frecuencia
flutter-table-column-4 = amortiguamiento
flutter-table-column-5 = amplitud
flutter-table-column-6 = remedio
flutter-table-resonance-1 = Resonancia forzada (para comparar)
flutter-table-resonance-2 = una fuerza exterior que oscila cerca de ωₙ (pasos al marchar, un motor)
flutter-table-resonance-3 = la impone la fuerza; debe coincidir con ωₙ
flutter-table-resonance-4 = positivo: limita el pico a unas 1/(2ζ) veces el valor estático
flutter-table-resonance-5 = régimen permanente acotado
flutter-table-resonance-6 = desintonizar o añadir amortiguamiento
flutter-table-underdamped-1 = Viento por debajo de U_crit
flutter-table-underdamped-2 = viento constante; momento ∝ velocidad de giro (A₂*) y giro (A₃*)
flutter-table-underdamped-3 = la propia del tablero, algo desplazada por A₃*
flutter-table-underdamped-4 = ζ_eff > 0: A₂* por debajo del umbral 4Iζ_s/(ρB⁴)
flutter-table-underdamped-5 = un giro se extingue
flutter-table-underdamped-6 = —
flutter-table-undamped-1 = En U_crit
flutter-table-undamped-2 = viento constante; momento ∝ velocidad de giro (A₂*) y giro (A₃*)
flutter-table-undamped-3 = la propia del tablero
flutter-table-undamped-4 = ζ_eff = 0: polos sobre el eje imaginario
flutter-table-undamped-5 = un giro persiste sin cambios
flutter-table-undamped-6 = —
flutter-table-negatively-damped-1 = Flameo, viento por encima de U_crit
flutter-table-negatively-damped-2 = viento constante; el movimiento crea su propia excitación
flutter-table-negatively-damped-3 = la propia del tablero, sin necesidad de coincidir
flutter-table-negatively-damped-4 = ζ_eff < 0: entra energía en cada ciclo
flutter-table-negatively-damped-5 = crece hasta la cota de amplitud (o hasta que cede el tablero)
flutter-table-negatively-damped-6 = una sección cuyo A₂* siga siendo negativo: tablero aerodinámico, abierto o rigidizado

### nonlinear

nonlinear-title = Más allá del modelo lineal
nonlinear-summary = Una suspensión real solo es lineal para movimientos pequeños. Aquí el cuarto de vehículo tiene un resorte cúbico (k₃ > 0 rigidizante, k₃ < 0 ablandante), un amortiguador más duro en rebote (x′ > 0) que en compresión, fricción de Coulomb en las articulaciones y topes de goma más allá de ±gap. La fricción alterna adherencia y deslizamiento: mientras la masa desliza, frena con la fuerza F_c; cuando se detiene, la fricción estática la sujeta hasta F_static, un múltiplo fijo de F_c, y solo vuelve a moverse si el resorte tira con más fuerza. El movimiento se integra con RK4, localizando cada parada dentro de su paso, y se dibuja frente al modelo lineal m·x″ + c̄·x′ + k·x = 0 (c̄ la constante media del amortiguador) desde el mismo inicio. Observe dónde falla la predicción: el periodo depende de la amplitud (el resorte rigidizante lo acorta, el ablandante lo alarga), la fricción hace caer la amplitud en línea recta y luego retiene la masa descentrada para siempre (adherencia-deslizamiento), un tope convierte una oscilación suave en un impacto, y un amortiguador asimétrico desplaza la posición media. Los valores por defecto son una esquina de coche verosímil: 300 kg, 24 kN/m (1,4 Hz), un amortiguador de 1 500 N·s/m (ζ ≈ 0,28) y un resorte algo progresivo. x es la extensión de la suspensión desde el equilibrio estático (positiva = carrocería hacia arriba).
nonlinear-param-m = masa suspendida
nonlinear-param-k = rigidez lineal del resorte
nonlinear-param-k3 = coeficiente cúbico del resorte (+ rigidizante, − ablandante)
nonlinear-param-c-comp = constante del amortiguador en compresión
nonlinear-param-c-reb = constante del amortiguador en rebote
nonlinear-param-friction = fuerza de fricción de Coulomb al deslizar
nonlinear-param-stick-ratio = razón entre fricción estática y de deslizamiento
nonlinear-param-gap = holgura hasta el tope
nonlinear-param-k-stop = rigidez del tope (0 = sin topes)
nonlinear-param-x0 = extensión inicial
nonlinear-param-v0 = velocidad inicial
nonlinear-readout-effect = no linealidad dominante
nonlinear-readout-period-ratio = razón de periodos de la primera oscilación T_nonlinear / T_linear
nonlinear-readout-max-deviation = máximo de |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = periodo no lineal de la primera oscilación completa (tres pasos por cero)
nonlinear-readout-period-linear = periodo lineal de la primera oscilación completa (= 2π/ω_d)
nonlinear-readout-max-travel = máximo de |x| (no lineal)
nonlinear-readout-stick-position = la fricción retiene la masa en
nonlinear-plot-response = Respuesta no lineal y lineal x(t)
nonlinear-plot-phase = Plano de fase (x, v)
nonlinear-plot-spring = Fuerza del resorte y de los topes
nonlinear-plot-damper = Fuerza del amortiguador y de la fricción
nonlinear-preset-1 = Lineal (todo desactivado)
nonlinear-preset-2 = Resorte rigidizante
nonlinear-preset-3 = Resorte ablandante
nonlinear-preset-4 = Fricción con adherencia–deslizamiento
nonlinear-preset-5 = Impacto contra el tope
nonlinear-preset-6 = Amortiguador asimétrico
nonlinear-table-caption = Dónde falla el modelo lineal
nonlinear-table-column-1 = no linealidad
nonlinear-table-column-2 = ley de fuerza
nonlinear-table-column-3 = qué no capta el modelo lineal
nonlinear-table-column-4 = huella en las gráficas
nonlinear-table-linear-1 = Ninguna (lineal)
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = nada: el modelo es exacto
nonlinear-table-linear-4 = las dos curvas coinciden
nonlinear-table-hardening-spring-1 = Resorte rigidizante
nonlinear-table-hardening-spring-2 = k·x + k₃·x³, k₃ > 0
nonlinear-table-hardening-spring-3 = la frecuencia aumenta con la amplitud
nonlinear-table-hardening-spring-4 = periodo más corto mientras la oscilación es grande; las curvas se separan
nonlinear-table-softening-spring-1 = Resorte ablandante
nonlinear-table-softening-spring-2 = k·x + k₃·x³, k₃ < 0
nonlinear-table-softening-spring-3 = la frecuencia disminuye con la amplitud; más allá de √(−k/k₃) el resorte cede
nonlinear-table-softening-spring-4 = periodo más largo; un inicio grande puede escaparse
nonlinear-table-stick-slip-1 = Fricción de Coulomb
nonlinear-table-stick-slip-2 = F_c·sgn(x′) al deslizar; hasta F_static en reposo
nonlinear-table-stick-slip-3 = la amplitud cae unos 4F_c/k por ciclo, en línea recta, y luego la masa se queda pegada para siempre donde |k·x| ≤ F_static
nonlinear-table-stick-slip-4 = envolvente recta; un final plano fuera de cero
nonlinear-table-bump-stop-impact-1 = Topes de suspensión
nonlinear-table-bump-stop-impact-2 = k_stop·(|x| − gap) más allá de ±gap
nonlinear-table-bump-stop-impact-3 = un contacto rígido y súbito: fuerza grande, inversión rápida
nonlinear-table-bump-stop-impact-4 = picos recortados en ±gap; quiebros en el lazo de fase
nonlinear-table-asymmetric-damper-1 = Amortiguador asimétrico
nonlinear-table-asymmetric-damper-2 = c_r·x′ en rebote, c_c·x′ en compresión
nonlinear-table-asymmetric-damper-3 = un desplazamiento de la posición media (efecto «jacking») y semiciclos desiguales
nonlinear-table-asymmetric-damper-4 = decaimiento asimétrico; la espiral de fase está descentrada
nonlinear-table-several-at-once-1 = Varias a la vez
nonlinear-table-several-at-once-2 = suma de las anteriores
nonlinear-table-several-at-once-3 = sus efectos se suman e interactúan
nonlinear-table-several-at-once-4 = ver cada fila
nonlinear-table-escaped-1 = Resorte ablandante más allá de su límite
nonlinear-table-escaped-2 = k·x + k₃·x³ < 0 para |x| > √(−k/k₃)
nonlinear-table-escaped-3 = el modelo deja de describir una suspensión
nonlinear-table-escaped-4 = la simulación se corta donde |x| supera 1 m

### quarter-car-2dof

quarter-car-2dof-title = Cuarto de vehículo con carrocería y rueda
quarter-car-2dof-summary = Dos masas, dos modos. La carrocería (masa suspendida m_s) descansa sobre el resorte de suspensión k_s y el amortiguador c_s; la rueda (masa no suspendida m_u) descansa sobre el resorte del neumático k_t, que sigue a la carretera u(t). El rebote de la carrocería, en torno a 1–1,5 Hz, es la carrocería moviéndose sobre la suspensión blanda; el salto de la rueda, en torno a 10–15 Hz, es la rueda ligera rebotando entre el neumático rígido y la suspensión. Las respuestas en frecuencia muestran ambos: la carrocería sigue las ondulaciones lentas de la carretera, pasa por encima de las rápidas y vibra más cerca del rebote de la carrocería; la deflexión del neumático, que determina el agarre, tiene su pico en el salto de la rueda. El neumático solo puede empujar: cuando la rueda sube por encima de su deflexión estática, la fuerza del neumático es cero y la rueda despega de la carretera hasta que vuelve a apoyarse. El confort se juzga por la aceleración RMS de la carrocería y el agarre por la deflexión RMS del neumático, ambas durante la marcha desde el reposo, 0 … T. La respuesta es exacta entre las muestras de la carretera, tan próximas que siguen cada bache y cada salto de la rueda. Los desplazamientos se miden desde el equilibrio estático, positivos hacia arriba; la carretera aleatoria suma 64 sinusoides con el espectro ISO 8608 entre 0,5 y 20 Hz. Sobre ella la página muestra también la aceleración RMS estacionaria de la carrocería en la carretera ISO 8608 completa, sin ponderar y ponderada con W_k de ISO 2631-1 (a_w, la medida de confort), a partir de la ecuación de Lyapunov del vehículo.
quarter-car-2dof-param-ms = masa de la carrocería (suspendida)
quarter-car-2dof-param-mu = masa de la rueda (no suspendida)
quarter-car-2dof-param-ks = rigidez de la suspensión
quarter-car-2dof-param-kt = rigidez del neumático
quarter-car-2dof-param-cs = amortiguamiento de la suspensión
quarter-car-2dof-param-road = excitación de la carretera
quarter-car-2dof-param-road-bump = resalto único (1 − cos)
quarter-car-2dof-param-road-step = escalón (bordillo)
quarter-car-2dof-param-road-sine = sinusoide
quarter-car-2dof-param-road-random = carretera aleatoria (ISO 8608)
quarter-car-2dof-param-h = altura del resalto o del escalón, amplitud del seno
quarter-car-2dof-param-L = longitud del resalto
quarter-car-2dof-param-V = velocidad
quarter-car-2dof-param-f-road = frecuencia de la carretera sinusoidal
quarter-car-2dof-param-class = clase de carretera aleatoria
quarter-car-2dof-param-class-A = A (muy buena)
quarter-car-2dof-param-class-B = B (buena)
quarter-car-2dof-param-class-C = C (media)
quarter-car-2dof-param-class-D = D (mala)
quarter-car-2dof-param-class-E = E (muy mala)
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = semilla de la carretera aleatoria
quarter-car-2dof-readout-f-body = frecuencia de rebote de la carrocería
quarter-car-2dof-readout-f-wheel = frecuencia de salto de la rueda
quarter-car-2dof-readout-window = ventana del RMS: la marcha desde el reposo, 0 … T
quarter-car-2dof-readout-rms-body-accel = aceleración RMS de la carrocería en 0 … T (confort)
quarter-car-2dof-readout-rms-tyre-deflection = deflexión RMS del neumático z_u − u en 0 … T (agarre)
quarter-car-2dof-readout-max-travel = recorrido máximo de la suspensión |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = deflexión estática del neumático (más allá, la rueda despega)
quarter-car-2dof-readout-lift-off = primer despegue: la fuerza del neumático llega a cero
quarter-car-2dof-readout-airborne-time = tiempo con la rueda en el aire
quarter-car-2dof-readout-rms-road = altura RMS de la carretera (carretera aleatoria)
quarter-car-2dof-readout-stationary-accel = aceleración RMS estacionaria de la carrocería, carretera ISO 8608 completa (carretera aleatoria)
quarter-car-2dof-readout-stationary-weighted-accel = a_w estacionaria: aceleración RMS de la carrocería ponderada con W_k de ISO 2631-1 (carretera aleatoria)
quarter-car-2dof-readout-body-gain = amplitud carrocería / carretera a la frecuencia del seno
quarter-car-2dof-readout-tyre-gain = deflexión del neumático / amplitud de la carretera a la frecuencia del seno
quarter-car-2dof-plot-motion = Carrocería, rueda y carretera
quarter-car-2dof-plot-accel = Aceleración de la carrocería
quarter-car-2dof-plot-frf = Respuesta en frecuencia por unidad de altura de la carretera
quarter-car-2dof-plot-tyre = Deflexión del neumático
quarter-car-2dof-preset-1 = Resalto de 5 cm a 10 m/s
quarter-car-2dof-preset-2 = Bordillo de 5 cm
quarter-car-2dof-preset-3 = Ondulación a la frecuencia de rebote de la carrocería
quarter-car-2dof-preset-4 = Ondulación a la frecuencia de salto de la rueda
quarter-car-2dof-preset-5 = Carretera aleatoria, clase C, 20 m/s
quarter-car-2dof-preset-6 = Amortiguador blando en una carretera mala

### design

design-title = Espacio de diseño (k, c)
design-summary = Cada celda del mapa es un cuarto de vehículo (masa suspendida m sobre un resorte k y un amortiguador c), coloreada según la métrica elegida: tiempo de establecimiento y rebote máximo de la respuesta libre al soltarlo desde el reposo en x₀ = 60 mm (no es una respuesta a un escalón: la banda y el rebote son relativos a x₀), transmisibilidad máxima, o el confort de marcha tal como lo mide ISO 2631-1: a_w, la aceleración RMS de la carrocería ponderada con el filtro W_k (cuánto siente una persona sentada cada frecuencia), estacionaria en una carretera aleatoria ISO 8608 a la velocidad V. Para el confort cada celda es el cuarto de vehículo de dos grados de libertad (esta carrocería sobre la rueda m_u y el neumático k_t elegidos abajo, con la ecuación de Lyapunov): los mismos números que la demo quarter-car-2dof para el mismo vehículo; las lecturas dan también el valor RMS sin ponderar. Las líneas a trazos unen diseños de igual coeficiente de amortiguamiento ζ = c/(2√(km)). El frente de Pareto reúne los diseños que ningún otro supera a la vez en confort y en establecimiento. Haga clic en el mapa (o en un punto del frente) para elegir un diseño; mueva la masa para ver cómo se desplaza todo el mapa.
design-param-m = masa suspendida
design-param-mu = confort: masa de la rueda (no suspendida)
design-param-kt = confort: rigidez del neumático
design-param-metric = métrica del mapa
design-param-metric-settling-time = tiempo de establecimiento (respuesta libre)
design-param-metric-peak-rebound = rebote máximo (respuesta libre)
design-param-metric-accel-rms = confort a_w (aceleración RMS de la carrocería ponderada con W_k)
design-param-metric-peak-transmissibility = transmisibilidad máxima |X/U|
design-param-band = banda de establecimiento, ± % de x₀ (respuesta libre)
design-param-road = carretera (ISO 8608)
design-param-road-a = clase A (muy buena)
design-param-road-b = clase B (buena)
design-param-road-c = clase C (media)
design-param-road-d = clase D (mala)
design-param-V = confort: velocidad
design-param-k-min = mapa: rigidez mínima del resorte
design-param-k-max = mapa: rigidez máxima del resorte
design-param-c-min = mapa: constante mínima del amortiguador
design-param-c-max = mapa: constante máxima del amortiguador
design-param-k = rigidez del resorte seleccionada
design-param-c = constante del amortiguador seleccionada
design-param-n = celdas de la malla por eje
design-readout-k = rigidez del resorte seleccionada k
design-readout-c = constante del amortiguador seleccionada c
design-readout-zeta = coeficiente de amortiguamiento ζ
design-readout-settling-time = tiempo de establecimiento dentro de la banda ± de x₀ (respuesta libre)
design-readout-overshoot = rebote máximo, % de x₀ (respuesta libre)
design-readout-accel-rms = a_w: aceleración RMS de la carrocería ponderada con W_k de ISO 2631-1 (cuarto de vehículo de dos grados de libertad, estacionaria en la carretera ISO 8608 a la velocidad V)
design-readout-accel-unweighted = aceleración RMS de la carrocería, sin ponderar (mismo vehículo y carretera)
design-readout-grid-size = tamaño de la malla (celdas)
design-readout-compute-time = tiempo de cálculo del barrido
design-plot-map = Métrica sobre (k, c) con líneas de ζ constante
design-plot-pareto = Confort frente a establecimiento: frente de Pareto
design-plot-response = Diseño seleccionado: respuesta libre x(t)
design-preset-1 = Mapa del tiempo de establecimiento, 300 kg, ζ ≈ 0,37
design-preset-2 = Vehículo cargado, 500 kg, mismos componentes
design-preset-3 = Mapa de confort en una carretera de clase C
design-preset-4 = Mapa del rebote máximo, diseño con ζ = 0,7
design-preset-5 = Malla fina de 160 × 160

### uncertainty

uncertainty-title = Análisis de tolerancias
uncertainty-summary = Los componentes reales no tienen exactamente su valor nominal. Elija el sistema: el cuarto de vehículo (masa suspendida m, resorte k y el amortiguador ajustado para ζ con la masa nominal; la masa varía ±dm según la carga del vehículo) o el circuito RLC serie (R, L y C, cada uno dentro de ±dR, ±dL, ±dC). Solo se usan los controles del sistema elegido; los del otro grupo se ignoran. Los intervalos exactos de ζ, ωₙ y Q salen de las esquinas de la caja de tolerancias. La simulación de Monte Carlo hace N sorteos de diseños (con semilla: la misma semilla da el mismo resultado), uniformes dentro de la tolerancia o normales con la tolerancia como 3σ. La proporción dentro de especificación es la fracción de sorteos con ζ dentro de la ventana de especificación y un tiempo de establecimiento al 5 % (soltando desde el reposo) no mayor que el límite.
uncertainty-param-system = sistema
uncertainty-param-system-suspension = suspensión de cuarto de vehículo
uncertainty-param-system-rlc = RLC serie
uncertainty-param-m = suspensión: masa suspendida
uncertainty-param-k = suspensión: rigidez del resorte
uncertainty-param-zeta = suspensión: ζ de diseño con la masa nominal
uncertainty-param-dm = suspensión: tolerancia de la masa ±
uncertainty-param-R = RLC: resistencia
uncertainty-param-L = RLC: inductancia
uncertainty-param-C = RLC: capacidad
uncertainty-param-dR = RLC: tolerancia de la resistencia ±
uncertainty-param-dL = RLC: tolerancia de la bobina ±
uncertainty-param-dC = RLC: tolerancia del condensador ±
uncertainty-param-dist = distribución de los componentes
uncertainty-param-dist-uniform = uniforme dentro de ±tolerancia
uncertainty-param-dist-normal = normal, tolerancia = 3σ
uncertainty-param-N = sorteos de Monte Carlo
uncertainty-param-seed = semilla aleatoria
uncertainty-param-zeta-lo = especificación: ζ mínimo
uncertainty-param-zeta-hi = especificación: ζ máximo
uncertainty-param-ts-max = especificación: tiempo de establecimiento máximo
uncertainty-param-hist = segundo histograma
uncertainty-param-hist-zeta = coeficiente de amortiguamiento ζ
uncertainty-param-hist-f0 = frecuencia natural f0
uncertainty-param-hist-q = factor de calidad Q
uncertainty-param-hist-bandwidth = ancho de banda
uncertainty-param-hist-settling-time = tiempo de establecimiento
uncertainty-readout-zeta-min = ζ, mínimo (exacto)
uncertainty-readout-zeta-max = ζ, máximo (exacto)
uncertainty-readout-wn-min = ωₙ, mínima (exacta)
uncertainty-readout-wn-max = ωₙ, máxima (exacta)
uncertainty-readout-Q-min = Q, mínimo (exacto)
uncertainty-readout-Q-max = Q, máximo (exacto)
uncertainty-readout-yield = proporción dentro de especificación
uncertainty-readout-zeta-p5 = ζ, percentil 5
uncertainty-readout-zeta-p95 = ζ, percentil 95
uncertainty-readout-Q-p5 = Q, percentil 5
uncertainty-readout-Q-p95 = Q, percentil 95
uncertainty-readout-draws = sorteos
uncertainty-readout-compute-time = tiempo de cálculo de Monte Carlo
uncertainty-plot-band = Banda de respuestas libres dentro de la tolerancia
uncertainty-plot-zeta-hist = Monte Carlo: coeficiente de amortiguamiento ζ
uncertainty-plot-hist = Monte Carlo: magnitud elegida
uncertainty-preset-1 = Diseño con ζ = 1 y masa ±10 %
uncertainty-preset-2 = Diseño con ζ = 0,7 y masa ±10 %
uncertainty-preset-3 = RLC con componentes al 5 %
uncertainty-preset-4 = RLC con componentes al 20 %

### paper

paper-title = El artículo, comprobado
paper-summary = Zeta Lab se construyó a partir de un artículo sobre ecuaciones diferenciales de segundo orden en sistemas mecánicos y eléctricos (Ihenacho, Samuel, Okechukwu et al., Science Publishing Group, 2026). Aquí están todas sus figuras y tablas, dibujadas en vivo por la demostración que las reproduce, y todas las cifras que afirma, comprobadas: cada afirmación muestra el valor del artículo, el valor que calcula la aplicación y un veredicto. Siga un enlace para abrir la demostración exactamente en ese estado.
paper-readout-claims = afirmaciones comprobadas
paper-readout-confirmed = afirmaciones confirmadas
paper-readout-differs = afirmaciones que difieren
paper-plot-fig1a = Figura 1(a)
paper-plot-fig1b = Figura 1(b)
paper-plot-fig2a = Figura 2(a)
paper-plot-fig2b = Figura 2(b)
paper-plot-fig3a = Figura 3(a)
paper-plot-fig3b = Figura 3(b)
paper-plot-fig4a = Figura 4(a)
paper-plot-fig4b = Figura 4(b)
paper-plot-fig5 = Figura 5
paper-plot-table1 = Tabla 1
paper-plot-table2 = Tabla 2
paper-plot-table3 = Tabla 3
